// Navigation to the first frame of a built site, the default scene and `?scene=`, 5 fresh
// browser contexts each (the measure of docs/web.md, for any site folder): used to try builds of
// the page against each other. Run from tests/web: node first_frame.mjs SITE_FOLDER
import { launch, openViewer, serve, settled } from "./support.mjs";
const dir = process.argv[2];
const site = await serve(dir);
const browser = await launch();
const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
// Each step's time since navigation, from the page's own clock (performance.now()): the page's
// script running, the .wasm ready, eframe started, the first frame on screen, settled.
for (const q of ["", "?scene=scenes/scene1_04.txt"]) {
  const times = [];
  const steps = { script: [], wasm: [], started: [], frame: [], settled: [] };
  for (let run = 0; run < 5; run++) {
    const { page, context, started } = await openViewer(browser, site.url + q);
    await page.waitForFunction(() => window.raytracer.frame_size() != null, null, { polling: 10 });
    const frame = await page.evaluate(() => performance.now());
    await settled(page);
    times.push(Date.now() - started);
    const mark = (name) => page.evaluate((n) => performance.getEntriesByName(n)[0]?.startTime ?? NaN, name);
    steps.script.push(await page.evaluate(() => performance.getEntriesByType("navigation")[0].domContentLoadedEventStart));
    steps.wasm.push(await mark("raytracer:wasm-ready"));
    steps.started.push(await mark("raytracer:started"));
    steps.frame.push(frame);
    steps.settled.push(await page.evaluate(() => performance.now()));
    await context.close();
  }
  const line = Object.entries(steps).map(([name, v]) => `${name} ${Math.round(median(v))}`).join(" · ");
  console.log(`${q || "default"}: median ${median(times)} ms (${times.join(", ")}); steps, ms since navigation (medians): ${line}`);
}
await browser.close();
site.server.close();
