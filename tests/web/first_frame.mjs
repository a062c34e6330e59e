// Navigation to the first frame of a built site, the default scene and `?scene=`, 5 fresh
// browser contexts each (the measure of docs/web.md, for any site folder): used to try builds of
// the page against each other. Run from tests/web: node first_frame.mjs SITE_FOLDER
import { launch, openViewer, serve, settled } from "./support.mjs";
const dir = process.argv[2];
const site = await serve(dir);
const browser = await launch();
const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
for (const q of ["", "?scene=scenes/scene1_04.txt"]) {
  const times = [];
  for (let run = 0; run < 5; run++) {
    const { page, context, started } = await openViewer(browser, site.url + q);
    await settled(page);
    times.push(Date.now() - started);
    await context.close();
  }
  console.log(`${q || "default"}: median ${median(times)} ms (${times.join(", ")})`);
}
await browser.close();
site.server.close();
