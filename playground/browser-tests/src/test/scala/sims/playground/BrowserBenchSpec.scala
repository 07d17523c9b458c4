package sims.playground

import org.scalatest.funsuite.AnyFunSuite
import sims.playground.BrowserBench.Row

/** The browser benchmark's report: SoftStep's ratios to each peer, and what they say of the aims. */
class BrowserBenchSpec extends AnyFunSuite:
  private def rows(soft: Double, planck: Double, matter: Double, rapier: Double, scene: String) = Seq(
    Row(scene, "SiMS ClassicStep", 9.0, ok = false, "1 outside"),
    Row(scene, "SiMS SoftStep", soft, ok = true, "0 outside"),
    Row(scene, "planck", planck, ok = true, "0 outside"),
    Row(scene, "matter-js", matter, ok = true, "0 outside"),
    Row(scene, "Rapier", rapier, ok = true, "0 outside"))

  private val report = BrowserBench.markdown(
    rows(soft = 1.0, planck = 4.0, matter = 2.0, rapier = 0.8, "ballpit-500") ++
      rows(soft = 2.0, planck = 3.0, matter = 1.0, rapier = 1.0, "chain-100"),
    "1000", "100", "200", "a browser", clockStep = 0.005)

  test("the ratios are SoftStep's time over each peer's, per scene") {
    assert(report.contains("| scene | SiMS SoftStep / planck | SiMS SoftStep / matter-js | SiMS SoftStep / Rapier |"))
    assert(report.contains("| ballpit-500 | 0.25 | 0.50 | 1.25 |"))
    assert(report.contains("| chain-100 | 0.67 | 2.00 | 2.00 |"))
  }

  test("the summary names the scenes where an aim is missed") {
    assert(report.contains("In this run SiMS SoftStep is faster than planck on every scene; " +
        "not faster than matter-js on chain-100; not within 1.5 times Rapier on chain-100."))
  }

  test("with the soft step in WebAssembly too, each soft step's ratios and aims") {
    val both = BrowserBench.markdown(
      rows(soft = 1.0, planck = 4.0, matter = 2.0, rapier = 0.8, "ballpit-500") :+
        Row("ballpit-500", "SiMS SoftStep Wasm", 0.6, ok = true, "0 outside"),
      "1000", "100", "200", "a browser", clockStep = 0.005)
    assert(both.contains("| scene | SiMS SoftStep / planck | SiMS SoftStep / matter-js | SiMS SoftStep / Rapier | " +
        "SiMS SoftStep Wasm / planck | SiMS SoftStep Wasm / matter-js | SiMS SoftStep Wasm / Rapier |"))
    assert(both.contains("| ballpit-500 | 0.25 | 0.50 | 1.25 | 0.15 | 0.30 | 0.75 |"))
    assert(both.contains("In this run SiMS SoftStep is faster than planck on every scene; faster than matter-js on " +
        "every scene; within 1.5 times Rapier on every scene. SiMS SoftStep Wasm is faster than planck on every scene; " +
        "faster than matter-js on every scene; within 1.5 times Rapier on every scene."))
  }

  test("the report says how long each engine's code is warmed up, and how many steps are timed") {
    assert(report.contains("steps a copy of the scene for 1000 ms, thrown away"))
    assert(report.contains("runs 100 steps before 200 timed steps"))
  }

  test("the report says how fine the page's clock reads") {
    assert(report.contains("its clock reads in steps of\n5.0 µs"))
  }

  test("the section replaces the old one and keeps the sections after it") {
    val document = "# Performance\n\n## Browser\n\nold figures\n\n## After\n\ntext\n"
    val updated = BrowserBench.withSection(document, "## Browser\n\nnew figures\n")
    assert(updated == "# Performance\n\n## Browser\n\nnew figures\n\n## After\n\ntext\n")
  }
