addSbtPlugin("org.scoverage" % "sbt-scoverage" % "2.3.1")
addSbtPlugin("org.scalameta" % "sbt-mdoc" % "2.7.2")
// JMH for the bench subproject (benchmarks only; the library does not depend on it).
addSbtPlugin("pl.project13.scala" % "sbt-jmh" % "0.4.7")
// Scala.js: the library, the scenes and the playground also build for the browser and Node.
addSbtPlugin("org.scala-js" % "sbt-scalajs" % "1.20.2")
