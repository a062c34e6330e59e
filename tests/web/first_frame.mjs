// Navigation to the first frame of built sites, the default scene and `?scene=`, 5 fresh browser
// contexts each (the measure of docs/web.md, for any site folder): used to try builds of the page
// against each other. Several sites are measured in turns, in one run, so that the machine's
// noise falls on each alike. Run from tests/web: node first_frame.mjs SITE_FOLDER [SITE_FOLDER…]
import { launch, openViewer, serve, settled } from "./support.mjs";
const dirs = process.argv.slice(2);
const sites = await Promise.all(dirs.map((dir) => serve(dir)));
const browser = await launch();
const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
const queries = { default: "", "?scene=scenes/scene1_04.txt": "?scene=scenes/scene1_04.txt" };
// Each step's time since navigation, from the page's own clock (performance.now()): the page's
// script running, the canvas and its WebGL context readied, the .wasm ready, eframe started, the
// first frame of the scene asked for on screen, settled (the frame of the current view at full
// quality, nothing pending).
const results = dirs.map(() => Object.fromEntries(Object.keys(queries).map((q) => [q, {
  times: [], steps: { script: [], canvas: [], wasm: [], started: [], frame: [], settled: [] },
}])));
for (let run = 0; run < 5; run++) {
  for (const [i, site] of sites.entries()) {
    for (const [name, q] of Object.entries(queries)) {
      const { times, steps } = results[i][name];
      const { page, context, started } = await openViewer(browser, site.url + q);
      const wanted = q ? "scene1_04.txt" : "default scene (embedded)";
      // The frame must be of the scene asked for (a build without frame_scene_epoch cannot say).
      await page.waitForFunction((scene) => {
        const handle = window.raytracer;
        const epoch = handle.frame_scene_epoch?.();
        return handle.scene_name() === scene && handle.frame_size() != null
          && (scene.startsWith("default") || epoch === undefined || epoch > 0n);
      }, wanted, { polling: 10 });
      const frame = await page.evaluate(() => performance.now());
      await settled(page);
      times.push(Date.now() - started);
      const mark = (n) => page.evaluate((m) => performance.getEntriesByName(m)[0]?.startTime ?? NaN, n);
      steps.script.push(await page.evaluate(() => performance.getEntriesByType("navigation")[0].domContentLoadedEventStart));
      steps.canvas.push(await mark("raytracer:canvas-ready"));
      steps.wasm.push(await mark("raytracer:wasm-ready"));
      steps.started.push(await mark("raytracer:started"));
      steps.frame.push(frame);
      steps.settled.push(await page.evaluate(() => performance.now()));
      await context.close();
    }
  }
}
for (const [i, dir] of dirs.entries()) {
  for (const [name, { times, steps }] of Object.entries(results[i])) {
    const line = Object.entries(steps).map(([step, v]) => `${step} ${Math.round(median(v))}`).join(" · ");
    console.log(`${dir} ${name}: median ${median(times)} ms (${times.join(", ")}); steps, ms since navigation (medians): ${line}`);
  }
}
await browser.close();
for (const site of sites) site.server.close();
