// A separate sbt project that uses SiMS as an ordinary dependency.
// Publish the library first, from the repository's top: ./sbt publishLocal
// then, here: ../../sbt run
scalaVersion := "3.3.6"
libraryDependencies += "io.github.sims-scala" %% "sims" % "0.1.0-SNAPSHOT"
