addSbtPlugin("org.scoverage" % "sbt-scoverage" % "2.3.1")
addSbtPlugin("org.scalameta" % "sbt-mdoc" % "2.7.2")
