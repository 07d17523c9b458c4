package sims.sweep.examples

import java.io.File
import java.nio.file.{Files, Path}
import org.scalatest.funsuite.AnyFunSuite
import sims.sweep.LocalBackend

class MainSpec extends AnyFunSuite:
  test("the command line: defaults, each option, and errors naming the argument"):
    val defaults = Main.parse(Seq()).toOption.get
    assert(!defaults.spark && !defaults.small && defaults.master == "local[*]" && defaults.out == Path.of("out"))
    val all = Main.parse(Seq("--backend", "spark", "--master", "local[2]", "--runs", "small", "--out", "x", "--threads", "3"))
    assert(all == Right(Main.Options(spark = true, threads = 3, master = "local[2]", small = true, out = Path.of("x"))))
    assert(Main.parse(Seq("--backend", "mpi")) == Left("--backend is local or spark, got 'mpi'"))
    assert(Main.parse(Seq("--threads", "0")) == Left("--threads needs a whole number at least 1, got '0'"))
    assert(Main.parse(Seq("--runs", "all")) == Left("--runs is full or small, got 'all'"))
    assert(Main.parse(Seq("--out")) == Left("--out needs a value"))
    assert(Main.parse(Seq("cannon")) == Left("unknown argument cannon"))

  test("the example's grid has 2,000 runs and its small grid 40"):
    assert(CannonSweep.parameters.size == 2000)
    assert(Main.SmallGrid.size == 40)
    assert(CannonSweep.parameters.names == Main.SmallGrid.names)

  test("the local back end runs where no Spark class is: the example's main on a classpath without Spark"):
    val classpath = sys.props("sims.sweep.runtimeClasspath")
    assert(classpath.split(File.pathSeparator).nonEmpty)
    assert(!classpath.toLowerCase.contains("spark-core"), "the runtime classpath should hold no Spark jar")
    val out = Files.createTempDirectory("sweep-local")
    val java = Path.of(sys.props("java.home"), "bin", "java").toString
    val process = ProcessBuilder(java, "-Djava.awt.headless=true", "-cp", classpath, "sims.sweep.examples.Main",
      "--runs", "small", "--threads", "2", "--out", out.toString).redirectErrorStream(true).start()
    val output = String(process.getInputStream.readAllBytes())
    assert(process.waitFor() == 0, output)
    assert(output.contains("40 runs of 300 steps on LocalBackend(2 threads)"), output)
    val expected = CannonSweep.sweep(Main.SmallGrid).run(LocalBackend(2))
    assert(Files.readString(out.resolve("cannon-sweep.csv")) == expected.toCsv)
    assert(Files.size(out.resolve("cannon-sweep.parquet")) > 40 * 8 * 8)
    assert(javax.imageio.ImageIO.read(out.resolve("cannon-sweep.png").toFile).getWidth > 300)
    // The shot matters: some runs knock boxes down and some knock none.
    assert(expected("fallen").contains(0.0) && expected("fallen").max >= 10)
