// The browser benchmark: every bench scene with SiMS (Scala.js: both steps linked to JavaScript,
// the soft step linked to WebAssembly too) and with planck, matter-js and Rapier (WebAssembly),
// each built from the same layout values, timed alike (a copy of the scene stepped for a while and
// thrown away, so that the browser has compiled the engine's code; then warm-up steps, then timed
// steps), and checked for sanity with the same criteria after the run.
import RAPIER from "./node_modules/@dimforge/rapier2d-compat/dist/rapier.mjs";

// Each engine steps a copy of each scene this long before its timed copy is built: the browser
// compiles a function to its fastest code only once it has run often (a chain's joint solver, run
// for the first time by chain-100, took twice its settled time in the first 300 steps).
const CodeWarmUpMillis = 1000;
const WarmUpSteps = 100;
const TimedSteps = 200;
const ChunkSteps = 10; // steps between the page's pauses, so that it stays responsive (the driver polls it)
const Iterations = 10; // velocity and position iterations, as in the JVM bench

// Each engine: build(layout) gives { step(), state() -> [x, y, angle]* in metres, y up, jointLengths() }.
const engines = {
  "SiMS ClassicStep": (name) => simsBench.world(name, "ClassicStep"),
  "SiMS SoftStep": (name) => simsBench.world(name, "SoftStep"),
  "SiMS SoftStep Wasm": (name) => simsBenchWasm.world(name, "SoftStep"),
  "planck": (name) => planckWorld(simsBench.layout(name)),
  "matter-js": (name) => matterWorld(simsBench.layout(name)),
  "Rapier": (name) => rapierWorld(simsBench.layout(name)),
};

function planckWorld(layout) {
  const pl = planck;
  const world = new pl.World({ gravity: new pl.Vec2(layout.gravity[0], layout.gravity[1]), allowSleep: false,
    continuousPhysics: false });
  const bodies = layout.bodies.map(([kind, x, y, a, b, fixed, density, friction, restitution, group]) => {
    const body = world.createBody({ type: fixed ? "static" : "dynamic", position: new pl.Vec2(x, y), allowSleep: false });
    const shape = kind === 0 ? new pl.Circle(a) : new pl.Box(a, b);
    body.createFixture(shape, { density: fixed ? 0 : density, friction, restitution, filterGroupIndex: group > 0 ? -group : 0 });
    return body;
  });
  const joints = layout.joints.map(([i, j]) =>
    world.createJoint(new pl.DistanceJoint({ frequencyHz: 0, dampingRatio: 0 }, bodies[i], bodies[j],
      bodies[i].getPosition(), bodies[j].getPosition())));
  return {
    step: () => world.step(layout.timeStep, Iterations, Iterations),
    state: () => bodies.flatMap((b) => [b.getPosition().x, b.getPosition().y, b.getAngle()]),
    jointLengths: () => joints.map((j) => { const p = j.getAnchorA(), q = j.getAnchorB(); return Math.hypot(q.x - p.x, q.y - p.y); }),
  };
}

// matter-js works in pixels with y down: 50 pixels to the metre, gravity scaled to match.
const MatterScale = 50;
function matterWorld(layout) {
  const M = Matter;
  const engine = M.Engine.create({ enableSleeping: false, positionIterations: Iterations, velocityIterations: Iterations });
  const g = Math.hypot(layout.gravity[0], layout.gravity[1]);
  engine.gravity.x = layout.gravity[0] / (g || 1);
  engine.gravity.y = -layout.gravity[1] / (g || 1);
  engine.gravity.scale = g * MatterScale * 1e-6; // px per ms^2
  const bodies = layout.bodies.map(([kind, x, y, a, b, fixed, density, friction, restitution, group]) => {
    const options = { isStatic: fixed, friction, restitution, frictionAir: 0, density: density * 1e-3,
      collisionFilter: { group: group > 0 ? -group : 0 } };
    return kind === 0
      ? M.Bodies.circle(x * MatterScale, -y * MatterScale, a * MatterScale, options)
      : M.Bodies.rectangle(x * MatterScale, -y * MatterScale, 2 * a * MatterScale, 2 * b * MatterScale, options);
  });
  M.Composite.add(engine.world, bodies);
  const joints = layout.joints.map(([i, j]) => M.Constraint.create({ bodyA: bodies[i], bodyB: bodies[j], stiffness: 1, damping: 0 }));
  M.Composite.add(engine.world, joints);
  const dtMillis = layout.timeStep * 1000;
  return {
    step: () => M.Engine.update(engine, dtMillis),
    state: () => bodies.flatMap((b) => [b.position.x / MatterScale, -b.position.y / MatterScale, -b.angle]),
    jointLengths: () => joints.map((c) => Math.hypot(c.bodyB.position.x - c.bodyA.position.x,
      c.bodyB.position.y - c.bodyA.position.y) / MatterScale),
  };
}

function rapierWorld(layout) {
  const R = RAPIER;
  const world = new R.World({ x: layout.gravity[0], y: layout.gravity[1] });
  world.timestep = layout.timeStep;
  const bodies = layout.bodies.map(([kind, x, y, a, b, fixed, density, friction, restitution, group]) => {
    const description = (fixed ? R.RigidBodyDesc.fixed() : R.RigidBodyDesc.dynamic().setCanSleep(false)).setTranslation(x, y);
    const body = world.createRigidBody(description);
    let collider = (kind === 0 ? R.ColliderDesc.ball(a) : R.ColliderDesc.cuboid(a, b))
      .setDensity(fixed ? 0 : density).setFriction(friction).setRestitution(restitution);
    // A no-collide group: its members are in group 2 and filter it out; every other collider is in group 1.
    if (group > 0) collider = collider.setCollisionGroups((0x0002 << 16) | 0xfffd);
    world.createCollider(collider, body);
    return body;
  });
  const joints = layout.joints.map(([i, j]) => {
    const p = bodies[i].translation(), q = bodies[j].translation();
    const length = Math.hypot(q.x - p.x, q.y - p.y);
    return [i, j, world.createImpulseJoint(R.JointData.rope(length, { x: 0, y: 0 }, { x: 0, y: 0 }), bodies[i], bodies[j], true)];
  });
  return {
    step: () => world.step(),
    free: () => world.free(),
    state: () => bodies.flatMap((b) => { const t = b.translation(); return [t.x, t.y, b.rotation()]; }),
    jointLengths: () => joints.map(([i, j]) => { const p = bodies[i].translation(), q = bodies[j].translation();
      return Math.hypot(q.x - p.x, q.y - p.y); }),
  };
}

// The JVM bench's sanity criteria (sims.bench.Sanity), on the state after the run.
function sanity(name, layout, engine) {
  const s = engine.state();
  if (s.some((v) => !Number.isFinite(v))) return [false, "NaN or infinite state"];
  const free = layout.bodies.map((b, i) => [b, i]).filter(([b]) => !b[5]);
  if (name.startsWith("ballpit")) {
    const [minX, minY, maxX] = layout.bounds;
    const outside = free.filter(([b, i]) => { const x = s[3 * i], y = s[3 * i + 1], r = b[3];
      return x - r < minX - 0.05 || x + r > maxX + 0.05 || y - r < minY - 0.05; }).length;
    return [outside === 0, `${outside} outside`];
  }
  if (name.startsWith("pyramid")) {
    let fallen = 0, worst = 0;
    for (const [b, i] of free) {
      const moved = Math.hypot(s[3 * i] - b[1], s[3 * i + 1] - b[2]);
      const turn = s[3 * i + 2], tilt = Math.abs(turn - Math.round(turn / (Math.PI / 2)) * (Math.PI / 2));
      worst = Math.max(worst, moved);
      if (moved > 0.5 || tilt > 0.2) fallen++;
    }
    return [fallen === 0, `${fallen} fallen, largest drift ${worst.toFixed(3)} m`];
  }
  if (name.startsWith("chain")) {
    const lengths = engine.jointLengths();
    let worst = 0;
    layout.joints.forEach(([i, j], k) => {
      const rest = Math.hypot(layout.bodies[j][1] - layout.bodies[i][1], layout.bodies[j][2] - layout.bodies[i][2]);
      worst = Math.max(worst, Math.abs(lengths[k] - rest) / rest);
    });
    return [worst <= 0.25, `largest stretch ${(100 * worst).toFixed(1)}%`];
  }
  return [true, "finite"];
}

// The smallest step of the page's clock, in ms: browsers coarsen it (to 0.1 ms in a page that is
// not cross-origin isolated), and a turn's time is only as fine as this.
function clockStep() {
  let step = Infinity;
  for (let k = 0; k < 50; k++) {
    const start = performance.now();
    let now = start;
    while (now === start) now = performance.now();
    step = Math.min(step, now - start);
  }
  return step;
}

function pause() { return new Promise((resolve) => setTimeout(resolve, 0)); }

// Every engine of a scene is built and warmed up, then the engines take turns: each turn steps
// each engine ChunkSteps steps (the order rotating from turn to turn), so that a change in the
// machine's load between two engines' runs falls on all of them alike. An engine's time is the
// median of its turns.
async function run() {
  await RAPIER.init();
  // The WebAssembly bundle, an ES module, sets simsBenchWasm once its binary is instantiated.
  await import("./wasm/main.js");
  const results = [];
  const status = document.getElementById("status");
  for (const name of simsBench.names) {
    const layout = simsBench.layout(name);
    const names = Object.keys(engines);
    for (const engineName of names) {
      status.textContent = `Compiling ${engineName} on a copy of ${name}…`;
      const copy = engines[engineName](name);
      const until = performance.now() + CodeWarmUpMillis;
      do {
        for (let c = 0; c < ChunkSteps; c++) copy.step();
        await pause();
      } while (performance.now() < until);
      if (copy.free) copy.free();
    }
    status.textContent = `Building ${name}…`;
    await pause();
    const built = names.map((engineName) => engines[engineName](name));
    for (let e = 0; e < built.length; e++) {
      status.textContent = `Warming up ${name} with ${names[e]}…`;
      for (let k = 0; k < WarmUpSteps; k += ChunkSteps) {
        for (let c = 0; c < ChunkSteps; c++) built[e].step();
        await pause();
      }
    }
    status.textContent = `Timing ${name}…`;
    const turns = names.map(() => []);
    for (let turn = 0; turn < TimedSteps / ChunkSteps; turn++) {
      for (let i = 0; i < built.length; i++) {
        const e = (i + turn) % built.length;
        const start = performance.now();
        for (let c = 0; c < ChunkSteps; c++) built[e].step();
        turns[e].push((performance.now() - start) / ChunkSteps);
        await pause();
      }
    }
    names.forEach((engineName, e) => {
      const sorted = [...turns[e]].sort((x, y) => x - y);
      const millis = (sorted[(sorted.length - 1) >> 1] + sorted[sorted.length >> 1]) / 2;
      const [ok, detail] = sanity(name, layout, built[e]);
      results.push({ scene: name, engine: engineName, millis, ok, detail });
    });
  }
  const table = document.getElementById("results");
  table.innerHTML = "<tr><th>scene</th><th>engine</th><th>ms/step</th><th>sanity</th></tr>" +
    results.map((r) => `<tr><td>${r.scene}</td><td>${r.engine}</td><td>${r.millis.toFixed(3)}</td><td>${r.ok ? "ok" : "FAILED"}: ${r.detail}</td></tr>`).join("");
  status.textContent = "Done.";
  window.benchResults = { codeWarmUpMillis: CodeWarmUpMillis, warmUpSteps: WarmUpSteps, timedSteps: TimedSteps, userAgent: navigator.userAgent,
    clockStepMillis: clockStep(), results };
}

run().catch((e) => { document.getElementById("status").textContent = "Failed: " + e; window.benchResults = { error: String(e) }; });
