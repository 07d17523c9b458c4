import java.io.File
import java.net.{URI, URL}
import scala.sys.process._
import sbt.ScmInfo

/** Where the project lives, for the published POM: the `origin` remote of the git clone that
  * publishes, so that the build holds no web address of its own. A clone without such a remote
  * (a local copy) has none, and Maven Central refuses to publish from it.
  */
object Release {

  /** The host and path of the origin remote, from `git@host:owner/name.git` or a web address. */
  private def origin(base: File): Option[(String, String)] = {
    val remote =
      try Some(Process(Seq("git", "config", "--get", "remote.origin.url"), base).!!(ProcessLogger(_ => ())).trim)
      catch { case _: RuntimeException => None }
    val scpLike = """[^@/]+@([^:/]+):(.+)""".r
    val addressLike = """[a-z+]+://(?:[^@/]+@)?([^/:]+)(?::\d+)?/(.+)""".r
    remote
      .collect {
        case scpLike(host, path) => (host, path)
        case addressLike(host, path) => (host, path)
      }
      .map { case (host, path) => (host, path.stripSuffix("/").stripSuffix(".git")) }
  }

  private def page(host: String, path: String): URL = new URI("https", host, "/" + path, null).toURL

  /** The repository's web page: https on the remote's host and path. */
  def homepage(base: File): Option[URL] = origin(base).map { case (host, path) => page(host, path) }

  /** The repository for the POM's scm section: its page and the git connection. */
  def scmInfo(base: File): Option[ScmInfo] =
    origin(base).map { case (host, path) =>
      ScmInfo(page(host, path), s"scm:git:${page(host, path)}.git", Some(s"scm:git:git@$host:$path.git"))
    }
}
