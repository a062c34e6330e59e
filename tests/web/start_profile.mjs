// Where the page's start spends its time: Chromium's sampling profiler (DevTools protocol) from
// navigation until the viewer has settled on its first frame, then the functions with the most
// time, their own and with what they call (the .wasm's functions by their Rust names). Used to
// find what to cut in the first frame (docs/web-first-frame.txt).
// Run from tests/web: node start_profile.mjs SITE_FOLDER [QUERY, e.g. "?scene=scenes/scene1_04.txt"]
import { launch, serve } from "./support.mjs";
const site = await serve(process.argv[2]);
const browser = await launch();
const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
const page = await context.newPage();
const cdp = await context.newCDPSession(page);
await cdp.send("Profiler.enable");
await cdp.send("Profiler.setSamplingInterval", { interval: 200 });
await cdp.send("Profiler.start");
await page.goto(site.url + (process.argv[3] ?? ""));
await page.waitForFunction(() => window.raytracer?.frame_size() != null && window.raytracer.settled(), null, { polling: 10 });
const { profile } = await cdp.send("Profiler.stop");
const nodes = new Map(profile.nodes.map((n) => [n.id, n]));
const parent = new Map();
for (const n of profile.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
const own = new Map();
const inclusive = new Map();
profile.samples.forEach((id, i) => {
  const ms = (profile.timeDeltas[i] ?? 0) / 1000;
  // Each function with its file (the page's own script: index.html).
  const file = (url) => (url ? new URL(url).pathname.split("/").pop() || "index.html" : "");
  const name = (n) => `${n.callFrame.functionName || "(anonymous)"} ${file(n.callFrame.url)}`;
  own.set(name(nodes.get(id)), (own.get(name(nodes.get(id))) ?? 0) + ms);
  const seen = new Set();
  for (let at = id; at !== undefined; at = parent.get(at)) {
    const key = name(nodes.get(at));
    if (!seen.has(key)) inclusive.set(key, (inclusive.get(key) ?? 0) + ms);
    seen.add(key);
  }
});
const top = (map, count) => [...map].sort((a, b) => b[1] - a[1]).slice(0, count)
  .map(([key, ms]) => `${ms.toFixed(1).padStart(8)} ms  ${key.slice(0, 160)}`).join("\n");
console.log(`own time (ms), the 25 longest:\n${top(own, 25)}\n\nwith what they call (ms), the 60 longest:\n${top(inclusive, 60)}`);
await browser.close();
site.server.close();
