// A separate sbt project that uses SiMS as an ordinary dependency.
// Publish the library first, from the repository's top: ./sbt publishLocal
// then, here: ../../sbt run
scalaVersion := "3.3.6"
// The library's version comes from git tags (`./sbt "print version"` at the top prints it);
// CI passes it in SIMS_VERSION. Without it: the newest version published locally.
libraryDependencies += "io.github.sims-scala" %% "sims" % sys.env.getOrElse("SIMS_VERSION", "latest.integration")
