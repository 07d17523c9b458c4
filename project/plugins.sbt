addSbtPlugin("org.scoverage" % "sbt-scoverage" % "2.3.1")
addSbtPlugin("org.scalameta" % "sbt-mdoc" % "2.7.2")
// JMH for the bench subproject (benchmarks only; the library does not depend on it).
addSbtPlugin("pl.project13.scala" % "sbt-jmh" % "0.4.7")
