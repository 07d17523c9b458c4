// Compares two or more builds of the bench page's SiMS in headless Chromium, as alternate.js does
// in Node: for the WebAssembly build, which Node 20 cannot run, and for a JavaScript build in the
// browser's own V8. Each build's world of the scene is made in one page, warmed up, then stepped
// in turns of 20 steps, the order reversed every other turn; prints each build's median time per
// step and its median ratio to the first build's time in the same turn.
//
//   node bench/browser/alternate-chromium.js <scene> <js|wasm> <seconds> <build> <build> [...]
//
// A JavaScript build is the `main.js` of `./sbt benchPage/fullLinkJS`; a WebAssembly build is the
// folder `./sbt benchPageWasm/fullLinkJS` writes (bench/browser/wasm/target/scala-*/sims-bench-page-wasm-opt),
// copied out before the next build. Needs Debian's `chromium` (`apt-get install chromium`).
const fs = require("fs");
const http = require("http");
const os = require("os");
const path = require("path");
const { spawn } = require("child_process");

const [scene, kind, seconds, ...builds] = process.argv.slice(2);
if (!scene || !["js", "wasm"].includes(kind) || !(Number(seconds) > 0) || builds.length < 2) {
  console.error("usage: node alternate-chromium.js <scene> <js|wasm> <seconds> <build> <build> [...]");
  process.exit(2);
}

// The page: each build loaded in turn (each sets a global the next one's load replaces), its
// world taken, then the turns; the results are logged to the console, which Chromium writes to
// its standard error.
const root = fs.mkdtempSync(path.join(os.tmpdir(), "sims-alternate-"));
builds.forEach((build, i) => {
  const to = path.join(root, `build${i}`);
  fs.mkdirSync(to);
  if (kind === "js") fs.copyFileSync(build, path.join(to, "main.js"));
  else for (const file of fs.readdirSync(build)) fs.copyFileSync(path.join(build, file), path.join(to, file));
});
fs.writeFileSync(path.join(root, "index.html"), `<!doctype html><script type="module">
const global = ${JSON.stringify(kind === "js" ? "simsBench" : "simsBenchWasm")};
const load = (i) => ${kind === "js"
  ? 'new Promise((ok, fail) => { const s = document.createElement("script"); s.src = "build" + i + "/main.js"; s.onload = ok; s.onerror = fail; document.head.appendChild(s); })'
  : 'import("./build" + i + "/main.js")'};
const worlds = [];
for (let i = 0; i < ${builds.length}; i++) {
  delete globalThis[global];
  await load(i);
  worlds.push(globalThis[global].world(${JSON.stringify(scene)}, "SoftStep"));
}
for (const world of worlds) for (let k = 0; k < 200; k++) world.step();
const times = worlds.map(() => []);
const end = performance.now() + ${1000 * Number(seconds)};
for (let turn = 0; performance.now() < end; turn++) {
  for (let j = 0; j < worlds.length; j++) {
    const i = turn % 2 === 0 ? j : worlds.length - 1 - j;
    const start = performance.now();
    for (let k = 0; k < 20; k++) worlds[i].step();
    times[i].push((performance.now() - start) / 20);
  }
}
const median = (values) => [...values].sort((a, b) => a - b)[values.length >> 1];
worlds.forEach((_, i) => console.log("RESULT " + i + " " + times[i].length + " " + median(times[i]) + " " +
  median(times[i].map((t, k) => t / times[0][k]))));
console.log("RESULT done");
</script>`);

// Served cross-origin isolated, so that the page's clock reads in steps of microseconds.
const types = { ".html": "text/html", ".js": "text/javascript", ".wasm": "application/wasm" };
const server = http.createServer((request, response) => {
  const file = path.join(root, path.normalize(decodeURIComponent(request.url.split("?")[0])));
  if (!file.startsWith(root) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
    response.writeHead(404);
    response.end();
    return;
  }
  response.writeHead(200, { "Content-Type": types[path.extname(file)] || "application/octet-stream",
    "Cross-Origin-Opener-Policy": "same-origin", "Cross-Origin-Embedder-Policy": "require-corp" });
  fs.createReadStream(file).pipe(response);
});
server.listen(0, "127.0.0.1", () => {
  const address = `http://127.0.0.1:${server.address().port}/index.html`;
  const chromium = spawn("chromium", ["--headless=new", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr",
    `--user-data-dir=${path.join(root, "profile")}`, address], { stdio: ["ignore", "ignore", "pipe"] });
  let buffered = "";
  // Chromium writes its profile until it has exited: the folder goes after that.
  const finish = (status) => {
    chromium.once("exit", () => {
      server.close();
      fs.rmSync(root, { recursive: true, force: true, maxRetries: 5 });
      process.exit(status);
    });
    chromium.kill();
  };
  const timeout = setTimeout(() => { console.error("no result from Chromium in time"); finish(1); }, 1000 * (Number(seconds) + 120));
  chromium.stderr.on("data", (chunk) => {
    buffered += chunk;
    let line;
    while ((line = buffered.indexOf("\n")) >= 0) {
      const text = buffered.slice(0, line);
      buffered = buffered.slice(line + 1);
      const result = text.match(/RESULT ([^"]*)/);
      if (!result) continue;
      if (result[1] === "done") {
        clearTimeout(timeout);
        finish(0);
        return;
      }
      const [i, turns, millis, ratio] = result[1].split(" ");
      console.log(`${builds[Number(i)]}  turns ${turns}  median ${Number(millis).toFixed(4)} ms/step  ` +
        `median ratio to first ${Number(ratio).toFixed(4)}`);
    }
  });
  chromium.on("error", (error) => {
    console.error(`cannot start chromium: ${error.message}`);
    fs.rmSync(root, { recursive: true, force: true });
    process.exit(1);
  });
});
