ThisBuild / scalaVersion := "3.3.6"
ThisBuild / organization := "io.github.sims-scala"
ThisBuild / version := "0.1.0-SNAPSHOT"
ThisBuild / scalacOptions ++= Seq("-deprecation", "-feature", "-unchecked")

// Property tests draw from one fixed seed, so CI runs are repeatable; change it to explore.
ThisBuild / Test / testOptions += Tests.Argument(TestFrameworks.ScalaTest, "-S", "20261121")

val scalaTestVersion = "3.2.19"

lazy val testDependencies = Seq(
  "org.scalatest" %% "scalatest" % scalaTestVersion % Test,
  "org.scalatestplus" %% "scalacheck-1-18" % "3.2.19.0" % Test,
  "org.scalacheck" %% "scalacheck" % "1.18.1" % Test
)

/** The library: only the Scala standard library at run time. */
lazy val root = (project in file("."))
  // `./sbt test` builds and runs them too.
  .aggregate(LocalProject("scenes"), LocalProject("examples"), LocalProject("docs"), LocalProject("bench"))
  .settings(
    name := "sims",
    description := "SiMS, the Simple Mechanics Simulator: a small 2D rigid-body physics library",
    licenses := List(License.MIT),
    homepage := None,
    // Source control of the project, for the POM (no web address: the scm connection only).
    pomExtra :=
      <scm>
        <connection>scm:git:git@github.com:sims-scala/sims.git</connection>
        <developerConnection>scm:git:git@github.com:sims-scala/sims.git</developerConnection>
      </scm>
      <developers>
        <developer>
          <id>sims-scala</id>
          <name>The SiMS for Scala contributors</name>
        </developer>
      </developers>,
    Compile / doc / scalacOptions ++= Seq("-doc-root-content", "docs/api-overview.md"),
    libraryDependencies ++= testDependencies,
    Test / parallelExecution := false,
    coverageMinimumStmtTotal := 90,
    coverageFailOnMinimum := true
  )

/** The one set of scenes (examples, benchmark and test scenes) the other projects build from,
  * and the tests that need whole scenes. Root's own tests cannot use it (sbt forbids the
  * cycle), so those tests live here; they see root's test helpers (`sims.SlowTest`, ...).
  */
lazy val scenes = (project in file("scenes"))
  .dependsOn(root % "compile->compile;test->test")
  .settings(
    name := "sims-scenes",
    publish / skip := true,
    libraryDependencies ++= testDependencies,
    Test / parallelExecution := false
  )

/** Headless runs, the renderer and the viewer of the scenes. */
lazy val examples = (project in file("examples"))
  .dependsOn(scenes)
  .settings(
    name := "sims-examples",
    publish / skip := true,
    libraryDependencies ++= testDependencies,
    run / fork := true,
    run / connectInput := true,
    // Runs start in the repository's root, so `out/` lands next to README.md.
    run / baseDirectory := (LocalRootProject / baseDirectory).value,
    // The forked run never has a console of its own: pass its output straight through and
    // tell it whether sbt's is a terminal, so the progress bar redraws in place only there.
    run / outputStrategy := Some(StdoutOutput),
    run / javaOptions += s"-Dsims.examples.terminal=${System.console() != null}",
    Test / fork := true,
    Test / javaOptions += "-Djava.awt.headless=true",
    // The README picture test compares docs/images with a fresh run of the main job.
    Test / javaOptions += s"-Dsims.root=${(LocalRootProject / baseDirectory).value}",
    Test / parallelExecution := false
  )

/** The documentation book in docs/: `./sbt test` compiles and runs every snippet with mdoc. */
// mdoc wants its input apart from the project's base directory: the base holds no sources.
lazy val docs = (project in file("target/mdoc-project"))
  .dependsOn(root)
  .enablePlugins(MdocPlugin)
  .settings(
    name := "sims-docs",
    publish / skip := true,
    // Build output stays out of docs/, which mdoc reads.
    target := (ThisBuild / baseDirectory).value / "target" / "docs",
    mdocIn := (ThisBuild / baseDirectory).value / "docs",
    mdocOut := target.value / "mdoc",
    // mdoc adds -deprecation and -unchecked itself; given twice, the compiler complains once
    // per snippet ("Flag -unchecked set repeatedly"). Deprecations are still reported.
    Compile / scalacOptions := Seq("-feature"),
    Test / test := mdoc.toTask("").value
  )

/** Benchmarks (JMH) of SiMS against jBox2D and dyn4j; the peers are bench-only dependencies. */
lazy val bench = (project in file("bench"))
  .dependsOn(scenes)
  .enablePlugins(JmhPlugin)
  .settings(
    name := "sims-bench",
    publish / skip := true,
    libraryDependencies ++= Seq(
      "org.jbox2d" % "jbox2d-library" % "2.2.1.1",
      "org.dyn4j" % "dyn4j" % "5.0.2"
    ),
    coverageEnabled := false,
    run / fork := true,
    run / javaOptions ++= Seq("-Xmx2g"),
    // Tools' output as it is (no log prefix), e.g. to compare `Dump` with Box2D's dump.
    run / outputStrategy := Some(StdoutOutput)
  )
