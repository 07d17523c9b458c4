addSbtPlugin("org.scoverage" % "sbt-scoverage" % "2.3.1")
