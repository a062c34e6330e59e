// The viewer's web build in a real browser: Debian's headless Chromium driven by playwright-core
// (cargo xtask web test builds the site and the native binary, then runs this with node --test).
// egui's canvas has no DOM to query: the tests drive it with the mouse, the keyboard and file
// drops at canvas coordinates, and read what is on screen through the page's `window.raytracer`
// handle and screenshots; the native command line is the oracle for every picture.
import { after, before, test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import {
  assertOnScreen, dropFile, dropFiles, env, launch, nativeRender, openViewer, pngToRgb, raytracer, serve,
  settled, temporaryFolder, viewOf,
} from "./support.mjs";

let browser;
let site;

before(async () => {
  // The site alone: the course scenes it serves are the ones the build put in it.
  site = await serve(env.site);
  browser = await launch();
});

after(async () => {
  await browser?.close();
  site?.server.close();
});


/** The TGA file `file` with its rows in the other order and its header unchanged: a picture
 * written top row first without saying so in the file. */
function upsideDown(file) {
  const tga = fs.readFileSync(file);
  const [width, height] = [tga.readUInt16LE(12), tga.readUInt16LE(14)];
  const flipped = Buffer.from(tga);
  const start = 18 + tga[0];
  for (let row = 0; row < height; row++) {
    tga.copy(flipped, start + row * width * 3, start + (height - 1 - row) * width * 3, start + (height - row) * width * 3);
  }
  return flipped;
}

/** The `diagnosis:` lines of the command line run with `args` in `folder`, which must find a
 * difference (exit status 3). */
function cliDiagnosis(args, folder) {
  try {
    raytracer(args, folder);
  } catch (error) {
    assert.equal(error.status, 3);
    return error.stdout.toString().split("\n").filter((l) => l.startsWith("diagnosis: ")).map((l) => l.slice(11));
  }
  assert.fail("the command line finds no difference");
}

/** A fresh page on `?scene=scenes/scene1_04.txt`, the scene open and its frame settled. */
async function openScene1_04() {
  const opened = await openViewer(browser, `${site.url}?scene=scenes/scene1_04.txt`);
  await opened.page.waitForFunction(() => window.raytracer.scene_name() === "scene1_04.txt");
  await settled(opened.page);
  return opened;
}

test("the page loads without a console error and shows the default scene's two images", async () => {
  const { page, context, errors } = await openViewer(browser, site.url);
  await settled(page);
  assert.equal(await page.evaluate(() => window.raytracer.scene_name()), "default scene (embedded)");
  const view = await viewOf(page);
  await assertOnScreen(page, nativeRender("assets/default_scene.txt", view));
  assert.deepEqual(errors, []);
  await context.close();
});

test("while the .wasm loads the spinner waits a second before it turns, and the canvas is drawn as the desktop window's", async () => {
  // Each turn of the spinner is a frame the browser's compositor draws; where WebGL is drawn on
  // the CPU those frames held up the viewer's start (docs/web-first-frame.txt). A slow load, made
  // here by holding the .wasm back 2 s, still shows it turning after its second.
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  const page = await context.newPage();
  let release;
  const held = new Promise((resolve) => { release = resolve; });
  await page.route("**/raytracer_bg.wasm", async (route) => {
    await held;
    await route.continue();
  });
  await page.goto(site.url);
  const turn = () => page.evaluate(() => getComputedStyle(document.querySelector("#notice .spinner")).transform);
  await page.waitForTimeout(500);
  assert.equal(await turn(), "none", "the spinner turns in the load's first second");
  await page.waitForTimeout(900);
  assert.match(await turn(), /^matrix/, "the spinner does not turn once the load takes more than a second");
  release();
  await page.waitForFunction(() => window.raytracer !== undefined, null, { timeout: 60_000 });
  await settled(page);
  const attributes = await page.evaluate(() => document.getElementById("viewer").getContext("webgl2").getContextAttributes());
  assert.equal(attributes.antialias, false, "the canvas is multisampled");
  assert.equal(attributes.depth, false, "the canvas has a depth buffer");
  assert.equal(await page.evaluate(() => getComputedStyle(document.getElementById("notice")).display), "none");
  await context.close();
});

test("?scene= opens a scene from the page's site, the same pixels as the native render", async () => {
  const { page, context, errors } = await openViewer(browser, `${site.url}?scene=scenes/scene1_02.txt`);
  await page.waitForFunction(() => window.raytracer.scene_name() === "scene1_02.txt");
  await settled(page);
  assert.match(await page.title(), /scene1_02\.txt/);
  const view = await viewOf(page);
  const native = nativeRender(path.join(env.scenes, "scene1_02.txt"), view);
  await assertOnScreen(page, native);
  const frame = await page.evaluate(() => Array.from(window.raytracer.colour_rgb()));
  assert.ok(Buffer.from(frame).equals(native.colour.rgb), "the frame's bytes are the native render's");
  assert.deepEqual(errors, []);
  await context.close();
});

test("?scene= shows that scene first: no frame of the default scene passes by while it comes, even late", async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  // At each of the page's frames, which scene the frame on screen is of (0: the default scene).
  await context.addInitScript(() => {
    window.framesSeen = [];
    const look = () => {
      const epoch = window.raytracer?.frame_scene_epoch();
      if (epoch !== undefined) window.framesSeen.push(Number(epoch));
      requestAnimationFrame(look);
    };
    requestAnimationFrame(look);
  });
  // The scene comes a second late, as from a slow site: the viewer starts without it.
  await context.route("**/scenes/scene1_02.txt", async (route) => {
    await new Promise((resolve) => setTimeout(resolve, 1000));
    await route.continue();
  });
  const page = await context.newPage();
  // Asked for once: by the page's script, beside the .wasm; the viewer takes that answer.
  const asked = [];
  page.on("request", (request) => new URL(request.url()).pathname === "/scenes/scene1_02.txt" && asked.push(request.url()));
  await page.goto(`${site.url}?scene=scenes/scene1_02.txt`);
  await page.waitForFunction(() => window.raytracer?.scene_name() === "scene1_02.txt", null, { timeout: 60_000 });
  await settled(page);
  // The scene's frame on screen has been looked at (the look runs at the page's next frame).
  await page.waitForFunction(() => window.framesSeen.length > 0, null, { timeout: 10_000 });
  const seen = await page.evaluate(() => window.framesSeen);
  assert.deepEqual([...new Set(seen)], [1], "every frame on screen is of the scene the address names");
  assert.equal(asked.length, 1, `the scene was asked for once: ${asked.join(", ")}`);
  await context.close();
});

test("?scene= elsewhere or missing says why, and the default scene stays", async () => {
  for (const [address, expected] of [
    ["https://example.com/scene.txt", /only scenes on this page's own site/],
    ["scenes/no_such_scene.txt", /404/],
  ]) {
    const { page, context } = await openViewer(browser, `${site.url}?scene=${encodeURIComponent(address)}`);
    await page.waitForFunction(() => window.raytracer.scene_error() !== undefined, null, { timeout: 30_000 });
    assert.match(await page.evaluate(() => window.raytracer.scene_error()), expected);
    assert.equal(await page.evaluate(() => window.raytracer.scene_name()), "default scene (embedded)");
    await context.close();
  }
});

test("a scene file dropped on the page opens, and a broken one says where it is wrong", async () => {
  const { page, context } = await openViewer(browser, site.url);
  await settled(page);
  const scene = path.join(env.scenes, "scene1_03.txt");
  await dropFile(page, "scene1_03.txt", fs.readFileSync(scene));
  await page.waitForFunction(() => window.raytracer.scene_name() === "scene1_03.txt");
  await settled(page);
  const native = nativeRender(scene, await viewOf(page));
  const frame = await page.evaluate(() => Array.from(window.raytracer.colour_rgb()));
  assert.ok(Buffer.from(frame).equals(native.colour.rgb));
  await dropFile(page, "broken.txt", Buffer.from("OrthographicCamera {\n  center 0 0 x\n}\n"));
  await page.waitForFunction(() => window.raytracer.scene_error() !== undefined);
  assert.match(await page.evaluate(() => window.raytracer.scene_error()), /broken\.txt:2:\d+/);
  assert.equal(await page.evaluate(() => window.raytracer.scene_name()), "scene1_03.txt");
  await context.close();
});

test("a drag on the colour image moves the view", async () => {
  const { page, context } = await openViewer(browser, `${site.url}?scene=scenes/scene1_02.txt`);
  await page.waitForFunction(() => window.raytracer.scene_name() === "scene1_02.txt");
  await settled(page);
  const before = await viewOf(page);
  const { colourAt } = await assertOnScreen(page, nativeRender(path.join(env.scenes, "scene1_02.txt"), before));
  const x = colourAt.x + before.width / 2;
  const y = colourAt.y + before.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let step = 1; step <= 10; step++) await page.mouse.move(x + 6 * step, y, { steps: 1 });
  await page.mouse.up();
  await settled(page);
  const afterDrag = await viewOf(page);
  assert.notDeepEqual(afterDrag.centre, before.centre, "the camera moved");
  // What is on screen is the native render of the moved view, saved as a scene by the page.
  const frame = await page.evaluate(() => Array.from(window.raytracer.colour_rgb()));
  const unmoved = nativeRender(path.join(env.scenes, "scene1_02.txt"), afterDrag).colour.rgb;
  assert.ok(!Buffer.from(frame).equals(unmoved), "the picture changed");
  await context.close();
});

test("a wrong image dropped on the page gets the command line's diagnosis", async () => {
  const scene = path.resolve(env.scenes, "scene1_04.txt");
  const { page, context } = await openScene1_04();
  // A student's picture written top row first without saying so in the file.
  const folder = temporaryFolder();
  raytracer(["-input", scene, "-size", "120", "80", "-output", "c.tga"], folder);
  const flipped = upsideDown(path.join(folder, "c.tga"));
  fs.writeFileSync(path.join(folder, "student.tga"), flipped);
  const cli = cliDiagnosis(["-input", scene, "-compare_output", "student.tga"], folder);
  // Each line: the statement's name and values, then what it means.
  assert.deepEqual(cli.map((l) => l.split(": ")[0]), ["flipped-vertically"]);
  await dropFile(page, "student_output.tga", flipped);
  await page.waitForFunction(() => window.raytracer.diagnosis().length > 0, null, { timeout: 60_000 });
  assert.deepEqual(await page.evaluate(() => window.raytracer.diagnosis()), cli);
  await context.close();
});

test("a depth image dropped under a name that says nothing is judged as depth, as the command line judges it", async () => {
  const scene = path.resolve(env.scenes, "scene1_04.txt");
  const { page, context } = await openScene1_04();
  // The course's depth image of scene1_04, written top row first, named "mine.tga": only its
  // content (every pixel grey) says it is a depth image; the page's kind is "colour".
  const folder = temporaryFolder();
  raytracer(["-input", scene, "-size", "200", "200", "-depth", "12", "17", "d.tga"], folder);
  const flipped = upsideDown(path.join(folder, "d.tga"));
  fs.writeFileSync(path.join(folder, "mine.tga"), flipped);
  const cli = cliDiagnosis(["-input", scene, "-compare_depth", "12", "17", "mine.tga"], folder);
  assert.deepEqual(cli.map((l) => l.split(": ")[0]), ["flipped-vertically"]);
  await dropFile(page, "mine.tga", flipped);
  await page.waitForFunction(() => window.raytracer.diagnosis().length > 0, null, { timeout: 60_000 });
  assert.deepEqual(await page.evaluate(() => window.raytracer.diagnosis()), cli);
  await context.close();
});

test("a colour and a depth image dropped at once are judged together, as the command line judges the pair; three are refused", async () => {
  const scene = path.resolve(env.scenes, "scene1_04.txt");
  const { page, context } = await openScene1_04();
  // A student's two images of the course's line, each written top row first.
  const folder = temporaryFolder();
  raytracer(["-input", scene, "-size", "200", "200", "-output", "c.tga", "-depth", "12", "17", "d.tga"], folder);
  const [colour, depth] = [upsideDown(path.join(folder, "c.tga")), upsideDown(path.join(folder, "d.tga"))];
  fs.writeFileSync(path.join(folder, "output1_04.tga"), colour);
  fs.writeFileSync(path.join(folder, "depth1_04.tga"), depth);
  const cli = cliDiagnosis(["-input", scene, "-compare_output", "output1_04.tga", "-compare_depth", "12", "17", "depth1_04.tga"], folder);
  assert.deepEqual(cli.map((l) => l.split(": ")[0]), ["flipped-vertically"]);
  // Three images at once: which two make the pair is not guessed; none is compared, and the
  // status says why.
  await dropFiles(page, [["output1_04.tga", colour], ["depth1_04.tga", depth], ["output1_04_old.tga", colour]]);
  await page.waitForFunction(() => /^3 images dropped at once/.test(window.raytracer.message() ?? ""), null, { timeout: 30_000 });
  assert.equal(
    await page.evaluate(() => window.raytracer.message()),
    "3 images dropped at once (output1_04.tga, depth1_04.tga, output1_04_old.tga): none was compared; " +
      "the viewer judges one colour image and its depth image together: drop those two, or one image alone",
  );
  assert.deepEqual(await page.evaluate(() => window.raytracer.compared()), []);
  await dropFiles(page, [["output1_04.tga", colour], ["depth1_04.tga", depth]]);
  await page.waitForFunction(() => window.raytracer.compared().length === 2 && window.raytracer.diagnosis().length > 0, null, { timeout: 60_000 });
  assert.deepEqual((await page.evaluate(() => window.raytracer.compared())).sort(), ["colour output1_04.tga", "depth depth1_04.tga"]);
  assert.deepEqual(await page.evaluate(() => window.raytracer.diagnosis()), cli);
  await context.close();
});

test("an image picked where the browser lets the page keep it is compared again when it changes", async () => {
  const scene = path.resolve(env.scenes, "scene1_04.txt");
  const { page, context } = await openScene1_04();
  const folder = temporaryFolder();
  raytracer(["-input", scene, "-size", "200", "200", "-output", "output1_04.tga"], folder);
  const right = fs.readFileSync(path.join(folder, "output1_04.tga"));
  const flipped = upsideDown(path.join(folder, "output1_04.tga"));
  fs.writeFileSync(path.join(folder, "student.tga"), flipped);
  const cli = cliDiagnosis(["-input", scene, "-compare_output", "student.tga"], folder);
  // Chromium's file picker, which headless Chromium cannot show, answers with a real file
  // handle: a file of the page's private file system, written as their program would.
  const write = (bytes) => page.evaluate(async (data) => {
    const root = await navigator.storage.getDirectory();
    const handle = await root.getFileHandle("output1_04.tga", { create: true });
    const writable = await handle.createWritable();
    await writable.write(Uint8Array.from(atob(data), (c) => c.charCodeAt(0)));
    await writable.close();
    window.showOpenFilePicker = async () => [handle];
  }, Buffer.from(bytes).toString("base64"));
  await write(flipped);
  // The left panel scrolled to its end: the Compare section's "…" (choose the image).
  await page.mouse.move(170, 500);
  await page.mouse.wheel(0, 3000);
  await page.waitForTimeout(500);
  await page.mouse.click(319, 241);
  await page.waitForFunction(() => window.raytracer.diagnosis().length > 0, null, { timeout: 60_000 });
  assert.deepEqual(await page.evaluate(() => window.raytracer.diagnosis()), cli);
  // Their program, fixed, writes the file again: compared again with no click.
  await write(right);
  await page.waitForFunction(() => /: match$/.test(window.raytracer.message() ?? ""), null, { timeout: 60_000 });
  assert.equal(await page.evaluate(() => window.raytracer.message()), "compared output1_04.tga: match");
  assert.deepEqual(await page.evaluate(() => window.raytracer.diagnosis()), []);
  // Another scene opened closes the comparison, and the watch with it: the file written again
  // is not compared (against a scene it is not of).
  await dropFiles(page, [["scene1_02.txt", fs.readFileSync(path.resolve(env.scenes, "scene1_02.txt"))]]);
  await page.waitForFunction(() => window.raytracer.scene_name() === "scene1_02.txt", null, { timeout: 60_000 });
  await settled(page);
  assert.deepEqual(await page.evaluate(() => window.raytracer.compared()), []);
  const opened = await page.evaluate(() => window.raytracer.message());
  await write(flipped);
  // Four times the page's look at a watched file (500 ms).
  await page.waitForTimeout(2_000);
  await settled(page);
  assert.deepEqual(await page.evaluate(() => window.raytracer.compared()), [], "the closed comparison's file was compared again");
  assert.equal(await page.evaluate(() => window.raytracer.message()), opened);
  await context.close();
});

test("an export downloads the files the command line writes for the same request, named after the scene", async () => {
  const { page, context } = await openViewer(browser, `${site.url}?scene=scenes/scene1_02.txt`);
  await page.waitForFunction(() => window.raytracer.scene_name() === "scene1_02.txt");
  await settled(page);
  const folder = temporaryFolder();
  const downloads = [];
  page.on("download", (download) => downloads.push(download));
  await page.locator("canvas").click({ position: { x: 5, y: 700 } });
  await page.keyboard.press("Control+s");
  await page.waitForFunction(() => /downloaded/.test(window.raytracer.message() ?? ""), null, { timeout: 60_000 });
  await page.waitForTimeout(500);
  const names = [];
  for (const download of downloads) {
    const name = download.suggestedFilename();
    names.push(name);
    await download.saveAs(path.join(folder, "page", name));
  }
  assert.deepEqual(names.sort(), [
    "scene1_02_both.png", "scene1_02_colour.png", "scene1_02_command.sh", "scene1_02_depth.png", "scene1_02_scene.txt",
  ]);
  // The downloaded command, run by the native binary beside the downloaded scene.
  const again = path.join(folder, "again");
  fs.mkdirSync(again);
  for (const name of ["scene1_02_command.sh", "scene1_02_scene.txt"]) {
    fs.copyFileSync(path.join(folder, "page", name), path.join(again, name));
  }
  execFileSync("sh", ["scene1_02_command.sh"], {
    cwd: again,
    env: { ...process.env, PATH: `${path.dirname(path.resolve(env.raytracer))}:${process.env.PATH}` },
  });
  for (const name of ["scene1_02_colour.png", "scene1_02_depth.png"]) {
    assert.ok(
      fs.readFileSync(path.join(again, name)).equals(fs.readFileSync(path.join(folder, "page", name))),
      `${name}: the page's download and the command line's file are the same bytes`,
    );
  }
  await context.close();
});

test("Course files downloads the bytes of the course's own command line, and says its range", async () => {
  const { page, context } = await openScene1_04();
  const downloads = [];
  page.on("download", (download) => downloads.push(download));
  // The left panel scrolled to its end: "Course files" is its last button, where the 1280×720
  // page lays it out.
  await page.mouse.move(170, 500);
  await page.mouse.wheel(0, 3000);
  await page.waitForTimeout(500);
  await page.mouse.click(50, 683);
  await page.waitForFunction(() => /downloaded/.test(window.raytracer.message() ?? ""), null, { timeout: 60_000 });
  assert.match(
    await page.evaluate(() => window.raytracer.message()),
    /^wrote the course's files for scene1_04\.txt \(its line's -size 200 200 -depth 12 17\): output1_04\.tga, depth1_04\.tga, command1_04\.sh \(downloaded\)$/,
  );
  await page.waitForTimeout(500);
  const folder = temporaryFolder();
  for (const download of downloads) {
    await download.saveAs(path.join(folder, "page", download.suggestedFilename()));
  }
  // The course's line for scene1_04, run by the native binary.
  raytracer(
    ["-input", path.resolve(env.scenes, "scene1_04.txt"), "-size", "200", "200", "-output", "output1_04.tga",
      "-depth", "12", "17", "depth1_04.tga"],
    folder,
  );
  assert.deepEqual(downloads.map((d) => d.suggestedFilename()).sort(), ["command1_04.sh", "depth1_04.tga", "output1_04.tga"]);
  assert.match(fs.readFileSync(path.join(folder, "page", "command1_04.sh"), "utf8"), /-size 200 200 -output output1_04\.tga -depth 12 17 depth1_04\.tga/);
  for (const name of ["output1_04.tga", "depth1_04.tga"]) {
    assert.ok(
      fs.readFileSync(path.join(folder, name)).equals(fs.readFileSync(path.join(folder, "page", name))),
      `${name}: the page's download and the course line's file are the same bytes`,
    );
  }
  await context.close();
});

test("every course scene and a dense scene render the native bytes in the page", async () => {
  const { page, context } = await openViewer(browser, site.url);
  await settled(page);
  const scenes = fs.readdirSync(env.scenes).filter((name) => /^scene1_0\d\.txt$/.test(name)).sort();
  assert.equal(scenes.length, 7);
  const dense = process.env.RAYTRACER_DENSE_SCENE;
  const files = scenes.map((name) => path.join(env.scenes, name));
  if (dense) files.push(dense);
  for (const file of files) {
    await dropFile(page, path.basename(file), fs.readFileSync(file));
    await page.waitForFunction((name) => window.raytracer.scene_name() === name, path.basename(file), { timeout: 60_000 });
    await settled(page);
    const native = nativeRender(file, await viewOf(page));
    const frame = await page.evaluate(() => Array.from(window.raytracer.colour_rgb()));
    assert.ok(Buffer.from(frame).equals(native.colour.rgb), `${path.basename(file)}: the page's frame is the native frame`);
  }
  assert.ok(dense, "RAYTRACER_DENSE_SCENE names the dense scene (cargo xtask web test makes it)");
  await context.close();
});

test("settings survive a reload of the page in the browser's storage", async () => {
  const { page, context } = await openViewer(browser, site.url);
  await settled(page);
  assert.equal(await page.evaluate(() => window.raytracer.colour_map()), "Grey");
  // The depth section's "turbo" radio button, where the 1280×720 page lays it out (below the
  // view's sliders, each with its name and value on a line above it: docs/screenshot.png).
  await page.mouse.click(141, 396);
  await page.waitForFunction(() => window.raytracer.colour_map() === "Turbo", null, { timeout: 10_000 });
  await page.reload();
  await page.waitForFunction(() => window.raytracer !== undefined, null, { timeout: 60_000 });
  await settled(page);
  assert.equal(await page.evaluate(() => window.raytracer.colour_map()), "Turbo");
  await context.close();
});

test("a scene named in other scripts shows its name in the browser's fonts, not as boxes", async () => {
  // Each word is dropped as a scene's name, and so is the same word in private-use characters,
  // which no font has: each drawn as egui's box. A word drawn as text differs from its boxes.
  // The status bar's message is compared from its separator on (the render time before it
  // changes from frame to frame).
  const { page, context, errors } = await openViewer(browser, site.url);
  await settled(page);
  const scene = fs.readFileSync(path.join(env.scenes, "scene1_01.txt"));
  const message = async (name) => {
    await dropFile(page, name, scene);
    await page.waitForFunction((n) => window.raytracer.scene_name() === n, name);
    await settled(page);
    await page.waitForTimeout(300);
    const size = page.viewportSize();
    const clip = { x: 0, y: size.height - 24, width: size.width, height: 24 };
    const { width, height, rgb } = pngToRgb(await page.screenshot({ clip }));
    const at = (x, y) => rgb.subarray((y * width + x) * 3, (y * width + x) * 3 + 3).toString("hex");
    const background = at(width - 2, height - 5);
    const separator = [...Array(width).keys()].find((x) => {
      const top = at(x, 5);
      return top !== background && [...Array(height - 10).keys()].every((y) => at(x, 5 + y) === top);
    });
    assert.ok(separator !== undefined, "no separator in the status bar");
    // A fixed span from the separator: the render time before it moves the separator by a few
    // pixels from one frame to the next ("9.8 ms", "12.4 ms"), and with it the row's length.
    const span = 480;
    assert.ok(separator + span <= width, `the separator at ${separator} leaves less than ${span} px`);
    return [...Array(height).keys()]
      .map((y) => rgb.subarray((y * width + separator) * 3, (y * width + separator + span) * 3).toString("hex"))
      .join("\n");
  };
  const boxed = [];
  for (const word of ["作业一", "場面", "장면", "мышь", "σκηνή", "مشهد"]) {
    const asBoxes = [...word].map((_, i) => String.fromCodePoint(0xe000 + i)).join("");
    if ((await message(`${word}.txt`)) === (await message(`${asBoxes}.txt`))) boxed.push(word);
  }
  assert.deepEqual(boxed, [], "words drawn as boxes");
  // And the comparison can tell: the same boxes twice are the same picture.
  assert.equal(await message("\ue000\ue001.txt"), await message("\ue000\ue001.txt"));
  assert.deepEqual(errors, []);
  await context.close();
});
