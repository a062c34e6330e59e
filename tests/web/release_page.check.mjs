// The page's release archive as a course would host it: unpacked and served by a plain static
// server (cargo xtask release test starts `python3 -m http.server` on the unpacked folder and
// names it in RAYTRACER_PAGE_URL). Headless Chromium shows a course scene with the native
// program's pixels, and the course scenes' menu opens another. Named `.check.mjs`, not
// `.test.mjs`: `node --test tests/web/` (cargo xtask web test) has no served archive to open.
import { after, before, test } from "node:test";
import assert from "node:assert/strict";
import path from "node:path";
import { assertOnScreen, env, launch, nativeRender, openViewer, settled, viewOf } from "./support.mjs";

const url = process.env.RAYTRACER_PAGE_URL;
const shots = process.env.RAYTRACER_SHOTS ?? ".";
let browser;

before(async () => {
  assert.ok(url, "RAYTRACER_PAGE_URL names the served page (cargo xtask release test)");
  browser = await launch();
});

after(async () => {
  await browser?.close();
});

test("the served page shows scene1_02 with the native program's pixels", async () => {
  const { page, context, errors } = await openViewer(browser, `${url}?scene=scenes/scene1_02.txt`);
  await page.waitForFunction(() => window.raytracer.scene_name() === "scene1_02.txt", null, { timeout: 60_000 });
  await settled(page);
  const native = nativeRender(path.join(env.scenes, "scene1_02.txt"), await viewOf(page));
  await assertOnScreen(page, native);
  await page.screenshot({ path: path.join(shots, "page-scene1_02.png") });
  assert.deepEqual(errors, []);
  await context.close();
});

test("the course scenes' menu opens a course scene", async () => {
  const { page, context, errors } = await openViewer(browser, url);
  await settled(page);
  assert.equal(await page.evaluate(() => window.raytracer.scene_name()), "default scene (embedded)");
  // The side panel scrolled to its end (the wheel over it), where the 1280×720 page lays out
  // the "Course scenes" button (the scene file section); then the menu's third row,
  // scene1_03.txt (page-menu.png shows both).
  await page.mouse.move(170, 500);
  await page.mouse.wheel(0, 2000);
  await page.waitForTimeout(800);
  await page.mouse.click(57, 453);
  await page.waitForTimeout(500);
  await page.screenshot({ path: path.join(shots, "page-menu.png") });
  await page.mouse.click(58, 526);
  await page.waitForFunction(() => window.raytracer.scene_name() === "scene1_03.txt", null, { timeout: 30_000 });
  await settled(page);
  const native = nativeRender(path.join(env.scenes, "scene1_03.txt"), await viewOf(page));
  await assertOnScreen(page, native);
  assert.deepEqual(errors, []);
  await context.close();
});
