import java.io.File
import sbt.io.IO
import sbt.util.Logger

/** The book's rendered pages: copied into docs/, compared with docs/, or put together with the
  * API reference into one folder.
  */
object Book {
  // Not a page of the book: the API reference's front page (Scaladoc's -doc-root-content).
  private val NotPages = Set("api-overview.md")

  private def pages(folder: File): Seq[File] =
    Option(folder.listFiles).toSeq.flatten.filter(f => f.isFile && f.getName.endsWith(".md")).sortBy(_.getName)

  /** Copies the rendered pages into `docs`, and removes pages there that no source renders. */
  def copyPages(rendered: File, docs: File, log: Logger): Unit = {
    val fresh = pages(rendered)
    for (page <- fresh) IO.copyFile(page, new File(docs, page.getName))
    val names = fresh.map(_.getName).toSet
    for (page <- pages(docs) if !names(page.getName) && !NotPages(page.getName)) {
      IO.delete(page)
      log.info(s"removed ${page.getName}: no source renders it")
    }
    log.info(s"rendered ${fresh.size} pages into $docs")
  }

  /** Fails, naming the pages, if docs/ is not what the sources render to. */
  def check(rendered: File, docs: File): Unit = {
    val fresh = pages(rendered).map(f => f.getName -> IO.read(f)).toMap
    val present = pages(docs).filterNot(f => NotPages(f.getName)).map(f => f.getName -> IO.read(f)).toMap
    val stale = fresh.keys.filter(name => present.get(name) != fresh.get(name)).toSeq.sorted
    val orphans = present.keys.filterNot(fresh.contains).toSeq.sorted
    if (stale.nonEmpty || orphans.nonEmpty)
      sys.error(
        (if (stale.isEmpty) "" else s"pages in docs/ differ from what their sources in docs/src render to: ${stale.mkString(", ")}; ") +
          (if (orphans.isEmpty) "" else s"pages in docs/ without a source in docs/src: ${orphans.mkString(", ")}; ") +
          "run ./sbt bookRender and commit the pages"
      )
  }

  /** The rendered pages, their pictures and the API reference (under api/) in `into`. */
  def assemble(rendered: File, images: File, api: File, into: File, log: Logger): File = {
    IO.delete(into)
    for (page <- pages(rendered)) IO.copyFile(page, new File(into, page.getName))
    IO.copyDirectory(images, new File(into, "images"))
    IO.copyDirectory(api, new File(into, "api"))
    log.info(s"the book in $into, the API reference in ${new File(into, "api")}")
    into
  }
}
