package sims.benchpage

/** The bench page's SiMS linked to WebAssembly (project `benchPageWasm`): offers the page the
  * same interface as [[Main]], as `window.simsBenchWasm`.
  */
object WasmMain:
  def main(args: Array[String]): Unit = Main.offer("simsBenchWasm")
