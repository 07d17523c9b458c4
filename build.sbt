ThisBuild / scalaVersion := "3.3.6"
ThisBuild / organization := "io.github.sims-scala"
// The version comes from git tags (sbt-dynver): tag v0.1.0 is version 0.1.0; commits after it,
// or a clone without tags, get `<last tag or 0.0.0>+<commits since>-<commit>` (plus a date when
// the work tree has changes). sbt-git reads the repository with the git command, which knows
// work trees (its built-in JGit does not). Its described version is not used (dynver makes
// the version) and would make git print "No names found" in a clone without tags.
useReadableConsoleGit
ThisBuild / git.gitDescribedVersion := None
ThisBuild / scalacOptions ++= Seq("-deprecation", "-feature", "-unchecked", "-Wunused:imports,privates,locals,implicits",
  // Unused code (E198) fails the build: none is left, and none creeps in.
  "-Wconf:id=E198:e")

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
  .aggregate(
    LocalProject("scenes"),
    LocalProject("examples"),
    LocalProject("sweep"),
    LocalProject("docs"),
    LocalProject("bench"),
    LocalProject("simsJS"),
    LocalProject("scenesJS"),
    LocalProject("playground"),
    LocalProject("playgroundWasm"),
    LocalProject("benchPage"),
    LocalProject("benchPageWasm"),
    LocalProject("browserTests")
  )
  .settings(
    name := "sims",
    description := "SiMS, the Simple Mechanics Simulator: a small 2D rigid-body physics library",
    licenses := List(License.MIT),
    // Publishing metadata for Maven Central (sbt-ci-release). The project's web address is its
    // git repository's: read from the `origin` remote of the clone that publishes (see
    // `Release` in project/), so that no address is written into the build.
    homepage := Release.homepage(baseDirectory.value),
    scmInfo := Release.scmInfo(baseDirectory.value),
    developers := List(Developer("sims-scala", "The SiMS for Scala contributors", "", homepage.value.orNull)),
    Compile / doc / scalacOptions ++= Seq("-doc-root-content", "docs/api-overview.md"),
    // The JVM's side of the platform objects (the worker threads); Scala.js has its own in js/.
    Compile / unmanagedSourceDirectories += baseDirectory.value / "src" / "main" / "scala-jvm",
    libraryDependencies ++= testDependencies,
    Test / parallelExecution := false,
    coverageMinimumStmtTotal := 90,
    coverageFailOnMinimum := true
  )

/** Test libraries for Scala.js: ScalaTest and ScalaCheck at the newest versions served for it; the
  * ScalaTest-ScalaCheck bridge is not published for Scala.js, so js/src/test holds a small one of
  * its own with the same name and the same `forAll` (see PropertyChecks there).
  */
lazy val jsTestDependencies = Def.setting(Seq(
    "org.scalatest" %%% "scalatest" % "3.2.18" % Test,
    "org.scalacheck" %%% "scalacheck" % "1.17.1" % Test
  ))

/** Tests of root and scenes that stay out of the Scala.js builds, and why. */
lazy val jvmOnlyTests = Set[String](
  "PortableMathSpec.scala", // compares with java.lang.StrictMath, which Scala.js lacks
  "ReadmeSpec.scala", // reads README.md from the disk
  "SoftBodiesLayoutSpec.scala",
  "DependenciesSpec.scala", // read the library's sources from the disk
  "ManifoldSpec.scala", // counts allocated bytes with the JVM's ThreadMXBean
  "StepAllocationSpec.scala", // the same
  "SoftStepWorkersSpec.scala", // counts the JVM's threads and what they allocate (Scala.js has one worker)
  "WorldCodecSpec.scala" // reads saved worlds from the class path's resources
)

/** The sources `project`'s tests share with Scala.js: all but the JVM-only ones. */
def sharedTests(base: File): Seq[File] = ((base / "src" / "test" / "scala") ** "*.scala").get.filterNot(f => jvmOnlyTests(f.getName))

/** The library for Scala.js, from root's own sources (src/main): artifact `sims_sjs1_3`. */
lazy val simsJS = (project in file("js"))
  .enablePlugins(ScalaJSPlugin)
  .settings(
    name := "sims",
    description := "SiMS, the Simple Mechanics Simulator: a small 2D rigid-body physics library (Scala.js)",
    licenses := List(License.MIT),
    homepage := (root / homepage).value,
    scmInfo := (root / scmInfo).value,
    developers := (root / developers).value,
    // root's sources and the Scala.js side of the platform objects (one worker, no threads).
    Compile / unmanagedSourceDirectories := Seq((root / baseDirectory).value / "src" / "main" / "scala",
      baseDirectory.value / "src" / "main" / "scala"),
    Test / unmanagedSources ++= sharedTests((root / baseDirectory).value),
    Compile / doc / scalacOptions ++= Seq("-doc-root-content", ((root / baseDirectory).value / "docs" / "api-overview.md").toString),
    libraryDependencies ++= jsTestDependencies.value,
    Test / parallelExecution := false,
    // The long simulations ran on the JVM already: the Node run keeps CI's time down without them.
    Test / testOptions += Tests.Argument(TestFrameworks.ScalaTest, "-l", "sims.SlowTest"),
    coverageEnabled := false
  )

/** The scenes for Scala.js, from the scenes' own sources; their Node tests see simsJS's tests. */
lazy val scenesJS = (project in file("scenes/js"))
  .enablePlugins(ScalaJSPlugin)
  .dependsOn(simsJS % "compile->compile;test->test")
  .settings(
    name := "sims-scenes",
    publish / skip := true,
    Compile / unmanagedSourceDirectories := Seq((scenes / baseDirectory).value / "src" / "main" / "scala"),
    Test / unmanagedSources ++= sharedTests((scenes / baseDirectory).value),
    libraryDependencies ++= jsTestDependencies.value,
    Test / parallelExecution := false,
    // The long simulations ran on the JVM already: the Node run keeps CI's time down without them.
    Test / testOptions += Tests.Argument(TestFrameworks.ScalaTest, "-l", "sims.SlowTest"),
    coverageEnabled := false
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
  // `examples/stage` writes a launcher script, examples/target/universal/stage/bin/sims-examples,
  // whose errors for a bad command line are the program's own (under `examples/run` sbt adds
  // its "nonzero exit code" lines, which read like a build failure).
  .enablePlugins(JavaAppPackaging)
  .settings(
    name := "sims-examples",
    publish / skip := true,
    Compile / mainClass := Some("sims.examples.Main"),
    executableScriptName := "sims-examples",
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

/** Spark for the sweep's Spark back end: its Scala 2.13 artifacts, which Scala 3 code can use
  * (the standard library is the same). Spark brings scala-xml for Scala 2.13, which clashes
  * with ScalaTest's for Scala 3 on one classpath; Spark's core does not need it to run jobs.
  */
val sparkVersion = "4.2.0"
def spark(module: String): ModuleID = ("org.apache.spark" %% module % sparkVersion)
  .cross(CrossVersion.for3Use2_13)
  .exclude("org.scala-lang.modules", "scala-xml_2.13")

/** What Spark opens of the JDK for itself (its launcher passes the same list). */
val sparkJavaOptions = Seq(
  "-XX:+IgnoreUnrecognizedVMOptions",
  "--add-opens=java.base/java.lang=ALL-UNNAMED",
  "--add-opens=java.base/java.lang.invoke=ALL-UNNAMED",
  "--add-opens=java.base/java.lang.reflect=ALL-UNNAMED",
  "--add-opens=java.base/java.io=ALL-UNNAMED",
  "--add-opens=java.base/java.net=ALL-UNNAMED",
  "--add-opens=java.base/java.nio=ALL-UNNAMED",
  "--add-opens=java.base/java.util=ALL-UNNAMED",
  "--add-opens=java.base/java.util.concurrent=ALL-UNNAMED",
  "--add-opens=java.base/java.util.concurrent.atomic=ALL-UNNAMED",
  "--add-opens=java.base/jdk.internal.ref=ALL-UNNAMED",
  "--add-opens=java.base/sun.nio.ch=ALL-UNNAMED",
  "--add-opens=java.base/sun.nio.cs=ALL-UNNAMED",
  "--add-opens=java.base/sun.security.action=ALL-UNNAMED",
  "--add-opens=java.base/sun.util.calendar=ALL-UNNAMED",
  "-Djdk.reflect.useDirectMethodHandle=false",
  "-Dio.netty.tryReflectionSetAccessible=true"
)

/** Parameter sweeps: many simulations of one scene over a table of parameters, on all local
  * cores (the default; no Spark needed) or on Spark. Spark is `Provided`: the local back end,
  * the CSV and the Parquet writer use none of it, and a Spark cluster brings its own.
  */
lazy val sweep = (project in file("sweep"))
  .dependsOn(scenes)
  .settings(
    name := "sims-sweep",
    publish / skip := true,
    libraryDependencies ++= testDependencies ++ Seq(
      spark("spark-core") % Provided,
      // Only for the tests, which read the sweep's Parquet files back with Spark's reader.
      spark("spark-sql") % Test
    ),
    run / fork := true,
    run / javaOptions ++= sparkJavaOptions,
    run / javaOptions += s"-Dlog4j2.configurationFile=${baseDirectory.value / "src" / "run" / "log4j2.properties"}",
    // Spark in local mode listens on the loopback address only.
    run / envVars += "SPARK_LOCAL_IP" -> "127.0.0.1",
    Test / envVars += "SPARK_LOCAL_IP" -> "127.0.0.1",
    Test / javaOptions += s"-Dlog4j2.configurationFile=${baseDirectory.value / "src" / "run" / "log4j2.properties"}",
    run / baseDirectory := (LocalRootProject / baseDirectory).value,
    run / outputStrategy := Some(StdoutOutput),
    // `sweep/run` runs with Spark on the classpath, for the example's `--backend spark`.
    Compile / run := Defaults.runTask(Compile / fullClasspath, Compile / run / mainClass, Compile / run / runner).evaluated,
    Compile / runMain := Defaults.runMainTask(Compile / fullClasspath, Compile / run / runner).evaluated,
    Compile / mainClass := Some("sims.sweep.examples.Main"),
    Test / fork := true,
    Test / javaOptions ++= sparkJavaOptions ++ Seq("-Djava.awt.headless=true", "-Xmx2g"),
    // What a program of the local back end alone runs with: no Spark (a test runs it so).
    Test / javaOptions += s"-Dsims.sweep.runtimeClasspath=${(Runtime / fullClasspath).value.files.mkString(java.io.File.pathSeparator)}",
    Test / parallelExecution := false,
    // `sweep/assembly`: the jar that spark-submit takes (the sweep, the scenes and the library,
    // and the Scala 3 library; Spark and Scala 2.13's library come with Spark).
    assembly / assemblyJarName := "sims-sweep-spark.jar",
    assembly / assemblyOption ~= (_.withIncludeScala(false)),
    assemblyMergeStrategy := {
      case PathList("META-INF", "MANIFEST.MF") => MergeStrategy.discard
      case other => (assembly / assemblyMergeStrategy).value(other)
    }
  )

/** Renders the book's sources into docs/, where readers of the repository see each snippet's result. */
val bookRender = taskKey[Unit]("Renders the book's sources (docs/src) into the pages in docs/")
/** Fails when a page in docs/ is not what its source renders to (run by `docs/test`). */
val bookCheck = taskKey[Unit]("Fails if a page in docs/ differs from its rendered source")
/** The book and the API reference in one folder. */
val book = taskKey[File]("Builds the book (rendered) and the API reference (Scaladoc) into target/book")

/** The documentation book: sources in docs/src/, rendered by mdoc into docs/ (checked in, so
  * that each snippet's printed result shows on a code host). `./sbt test` renders every
  * snippet again and fails if a page in docs/ differs from its fresh rendering.
  */
// mdoc wants its input apart from the project's base directory: the base holds no sources.
lazy val docs = (project in file("target/mdoc-project"))
  .dependsOn(sweep)
  .enablePlugins(MdocPlugin)
  .settings(
    name := "sims-docs",
    publish / skip := true,
    // The sweeps chapter shows the Spark back end's code (compiled, not run).
    libraryDependencies += spark("spark-core") % Provided,
    // Build output stays out of docs/.
    target := (ThisBuild / baseDirectory).value / "target" / "docs",
    mdocIn := (ThisBuild / baseDirectory).value / "docs" / "src",
    // A fresh rendering, compared with (or copied to) the pages in docs/.
    mdocOut := target.value / "mdoc",
    // mdoc adds -deprecation and -unchecked itself; given twice, the compiler complains once
    // per snippet ("Flag -unchecked set repeatedly"). Deprecations are still reported.
    Compile / scalacOptions := Seq("-feature"),
    bookRender := {
      mdoc.toTask("").value
      Book.copyPages(mdocOut.value, (ThisBuild / baseDirectory).value / "docs", streams.value.log)
    },
    bookCheck := {
      mdoc.toTask("").value
      Book.check(mdocOut.value, (ThisBuild / baseDirectory).value / "docs")
    },
    Test / test := bookCheck.value,
    book := {
      mdoc.toTask("").value
      val base = (ThisBuild / baseDirectory).value
      Book.assemble(mdocOut.value, base / "docs" / "images", (root / Compile / doc).value,
        base / "target" / "book", streams.value.log)
    }
  )

addCommandAlias("bookRender", "docs/bookRender")
// What CI will run once every source is formatted: fails on any file scalafmt would change.
addCommandAlias("formatCheck", "scalafmtCheckAll; scalafmtSbtCheck")
addCommandAlias("book", "docs/book")

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

/** Builds a subproject's page into a folder ready for static hosting (any web server, or a
  * local one): the page's own files and its fullLinkJS bundle.
  */
lazy val staticSite = taskKey[File]("the page and its optimised bundle, in one folder ready for static hosting")

/** A page's twin linked to WebAssembly by Scala.js's WebAssembly backend (an ES module, its loader
  * and `main.wasm`): the page's sources (the `src` of the folder above the twin's), no tests of its
  * own. Needs a browser with Wasm GC and exception handling (Chromium 137 or later); Node 20 has no
  * `exnref`, so the twins are tested in Chromium (`browserTests`), and Node cannot even load one to
  * look for test frameworks.
  */
lazy val wasmTwinSettings = Seq(
  publish / skip := true,
  Compile / unmanagedSourceDirectories += baseDirectory.value.getParentFile / "src" / "main" / "scala",
  scalaJSUseMainModuleInitializer := true,
  scalaJSLinkerConfig ~= (_.withExperimentalUseWebAssembly(true).withModuleKind(ModuleKind.ESModule)),
  Test / loadedTestFrameworks := Map.empty,
  coverageEnabled := false
)

/** Copies a WebAssembly link's output (the module, its loader and the binary; no source map) into `to`. */
def copyWasm(linked: File, to: File): Unit =
  IO.listFiles(linked).filterNot(_.getName.endsWith(".map")).foreach(f => IO.copyFile(f, to / f.getName))

/** The playground: one static page (playground/site) and its bundles, every scene on a canvas:
  * SiMS linked to WebAssembly (`playgroundWasm`, in `wasm/`), which the page runs where the browser
  * can, and to JavaScript (`playground.js`), which it runs elsewhere.
  */
lazy val playground = (project in file("playground"))
  .enablePlugins(ScalaJSPlugin)
  .dependsOn(scenesJS)
  .settings(
    name := "sims-playground",
    publish / skip := true,
    scalaJSUseMainModuleInitializer := true,
    libraryDependencies += "org.scala-js" %%% "scalajs-dom" % "2.8.1",
    coverageEnabled := false,
    staticSite := {
      val bundle = (Compile / fullLinkJS).value.data
      val bundleDirectory = (Compile / fullLinkJS / scalaJSLinkerOutputDirectory).value
      (playgroundWasm / Compile / fullLinkJS).value // linked, into:
      val wasmDirectory = (playgroundWasm / Compile / fullLinkJS / scalaJSLinkerOutputDirectory).value
      val out = target.value / "site"
      IO.delete(out)
      IO.copyDirectory(baseDirectory.value / "site", out)
      IO.copyFile(bundleDirectory / bundle.publicModules.head.jsFileName, out / "playground.js")
      copyWasm(wasmDirectory, out / "wasm")
      streams.value.log.info(s"playground: serve $out and open its address, or open ${out / "index.html"} (JavaScript)")
      out
    }
  )

/** The playground linked to WebAssembly: the same sources (playground/src). */
lazy val playgroundWasm = (project in file("playground/wasm"))
  .enablePlugins(ScalaJSPlugin)
  .dependsOn(scenesJS)
  .settings(wasmTwinSettings)
  .settings(
    name := "sims-playground-wasm",
    libraryDependencies += "org.scala-js" %%% "scalajs-dom" % "2.8.1"
  )

/** The playground in headless Chromium (Selenium and Debian's chromium-driver): the page, its
  * controls and mouse, and its fingerprints against the JVM's. Canceled, and counted as skipped
  * by .ci/run, where Chromium is not installed.
  */
lazy val browserBench = taskKey[Unit](
  "runs the browser benchmark page in headless Chromium; writes the Browser section of docs/src/performance.md (then ./sbt bookRender)")

lazy val browserTests = (project in file("playground/browser-tests"))
  .dependsOn(scenes % "test->test")
  .settings(
    name := "sims-browser-tests",
    publish / skip := true,
    coverageEnabled := false,
    libraryDependencies ++= testDependencies :+ ("org.seleniumhq.selenium" % "selenium-java" % "4.52.0" % Test),
    Test / fork := true,
    Test / javaOptions += s"-Dsims.playground.site=${(playground / staticSite).value}",
    Test / javaOptions += s"-Dsims.playground.screenshot=${target.value / "playground.png"}",
    Test / javaOptions += s"-Dsims.bench.bundles=${(benchPage / bundles).value}",
    Test / parallelExecution := false,
    browserBench := Def.taskDyn {
      val site = (benchPage / staticSite).value
      val document = (LocalRootProject / baseDirectory).value / "docs" / "src" / "performance.md"
      (Test / runMain).toTask(s" sims.playground.BrowserBench $site $document")
    }.value
  )

/** The bench page's SiMS bundles in one folder: `sims-bench.js` (fullLinkJS, JavaScript), and
  * `wasm/` (fullLinkJS of `benchPageWasm`, WebAssembly), with `bits.html`, the page that steps
  * both.
  */
lazy val bundles = taskKey[File]("the bench page's SiMS bundles, JavaScript and WebAssembly, in one folder")

/** The browser benchmark page (bench/browser/site): the bench scenes with SiMS (this bundle and
  * `benchPageWasm`'s) and with planck, matter-js and Rapier, installed from npm by `staticSite`
  * (bench/browser's package.json and package-lock.json) into the site folder under target/. Run it
  * with `./sbt browserTests/browserBench`, which writes the table into docs/src/performance.md.
  */
lazy val benchPage = (project in file("bench/browser"))
  .enablePlugins(ScalaJSPlugin)
  .dependsOn(scenesJS)
  .settings(
    name := "sims-bench-page",
    publish / skip := true,
    scalaJSUseMainModuleInitializer := true,
    Compile / mainClass := Some("sims.benchpage.Main"),
    coverageEnabled := false,
    bundles := {
      val bundle = (Compile / fullLinkJS).value.data
      val bundleDirectory = (Compile / fullLinkJS / scalaJSLinkerOutputDirectory).value
      (benchPageWasm / Compile / fullLinkJS).value // linked, into:
      val wasmDirectory = (benchPageWasm / Compile / fullLinkJS / scalaJSLinkerOutputDirectory).value
      val out = target.value / "bundles"
      IO.delete(out)
      IO.copyFile(bundleDirectory / bundle.publicModules.head.jsFileName, out / "sims-bench.js")
      copyWasm(wasmDirectory, out / "wasm")
      IO.copyFile(baseDirectory.value / "site" / "bits.html", out / "bits.html")
      out
    },
    staticSite := {
      val out = target.value / "site"
      val log = streams.value.log
      IO.copyDirectory(baseDirectory.value / "site", out, overwrite = true)
      IO.copyDirectory(bundles.value, out, overwrite = true)
      for (file <- Seq("package.json", "package-lock.json")) IO.copyFile(baseDirectory.value / file, out / file)
      if (!(out / "node_modules" / ".package-lock.json").exists) {
        log.info("bench page: installing the peers with npm ci")
        val status = scala.sys.process.Process(Seq("npm", "ci", "--no-audit", "--no-fund"), out).!
        if (status != 0) sys.error(s"npm ci failed with status $status")
      }
      out
    }
  )

/** The bench page's SiMS linked to WebAssembly: the same sources (bench/browser/src), offered to
  * the page as `simsBenchWasm`.
  */
lazy val benchPageWasm = (project in file("bench/browser/wasm"))
  .enablePlugins(ScalaJSPlugin)
  .dependsOn(scenesJS)
  .settings(wasmTwinSettings)
  .settings(
    name := "sims-bench-page-wasm",
    Compile / mainClass := Some("sims.benchpage.WasmMain")
  )
