// Compares two or more builds of the bench page's bundle in one Node process (the V8 engine of
// Chromium), as `sims.bench.Alternate` does on the JVM: the same scene is built from each
// bundle, warmed up, then stepped in turns of 5 steps, the order reversed every other turn, so
// that a change in the machine's load falls on every build alike. Prints each build's median
// time per step and its median ratio to the first build's time in the same turn. The bundle
// loaded first may run a few per cent faster whatever its code: run both orders, and take
// r = sqrt(ratio1 / ratio2).
//
//   node bench/browser/alternate.js <scene> <ClassicStep|SoftStep> <seconds> [--fresh] <bundle> <bundle> [...]
//
// With --fresh, the builds' worlds are made anew every round and timed over the steps the bench
// page times (its 100 warm-up steps, then 200 in turns of 10): a swinging chain, say, rather
// than one come to rest.
//
// A bundle is the `main.js` that `./sbt benchPage/fullLinkJS` writes (target/scala-*/sims-bench-page-opt).
const path = require("path");

const [scene, solver, seconds, ...rest] = process.argv.slice(2);
const fresh = rest[0] === "--fresh";
const bundles = fresh ? rest.slice(1) : rest;
if (!scene || !solver || !(Number(seconds) > 0) || bundles.length < 2) {
  console.error("usage: node alternate.js <scene> <ClassicStep|SoftStep> <seconds> [--fresh] <bundle> <bundle> [...]");
  process.exit(2);
}
const WarmUpSteps = 100;
const TurnSteps = fresh ? 10 : 5;
const RoundTurns = 20; // with --fresh: 200 timed steps a round, as the bench page times

// Each bundle sets globalThis.simsBench when loaded; the worlds keep their own bundle's code.
const makers = bundles.map((bundle) => {
  delete globalThis.simsBench;
  require(path.resolve(bundle));
  const bench = globalThis.simsBench;
  return () => bench.world(scene, solver);
});
const warmedUp = () => {
  const made = makers.map((make) => make());
  for (const world of made) for (let i = 0; i < WarmUpSteps; i++) world.step();
  return made;
};
let worlds = warmedUp();

const times = worlds.map(() => []);
const end = Date.now() + 1000 * Number(seconds);
for (let turn = 0; Date.now() < end; turn++) {
  if (fresh && turn > 0 && turn % RoundTurns === 0) worlds = warmedUp();
  const order = worlds.map((_, i) => (turn % 2 === 0 ? i : worlds.length - 1 - i));
  for (const i of order) {
    const start = process.hrtime.bigint();
    for (let k = 0; k < TurnSteps; k++) worlds[i].step();
    times[i].push(Number(process.hrtime.bigint() - start) / 1e6 / TurnSteps);
  }
}
const median = (values) => [...values].sort((x, y) => x - y)[values.length >> 1];
bundles.forEach((bundle, i) => {
  const ratio = median(times[i].map((t, k) => t / times[0][k]));
  console.log(`${bundle}  turns ${times[i].length}  median ${median(times[i]).toFixed(3)} ms/step  ` +
    `min ${Math.min(...times[i]).toFixed(3)}  median ratio to first ${ratio.toFixed(4)}`);
});
