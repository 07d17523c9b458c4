addSbtPlugin("org.scoverage" % "sbt-scoverage" % "2.3.1")
addSbtPlugin("org.scalameta" % "sbt-mdoc" % "2.7.2")
// JMH for the bench subproject (benchmarks only; the library does not depend on it).
addSbtPlugin("pl.project13.scala" % "sbt-jmh" % "0.4.7")
// Scala.js: the library, the scenes and the playground also build for the browser and Node.
addSbtPlugin("org.scala-js" % "sbt-scalajs" % "1.20.2")
// Releases: the version from git tags (sbt-dynver, which sbt-ci-release brings), signing and
// publishing to Maven Central from CI.
addSbtPlugin("com.github.sbt" % "sbt-ci-release" % "1.11.2")
// A staged launcher script for the examples' command line (examples/stage).
addSbtPlugin("com.github.sbt" % "sbt-native-packager" % "1.11.1")
// One jar of a sweep and everything it needs but Spark, for spark-submit (sweep/assembly).
addSbtPlugin("com.eed3si9n" % "sbt-assembly" % "2.3.1")
// Formatting (.scalafmt.conf).
addSbtPlugin("org.scalameta" % "sbt-scalafmt" % "2.5.5")
