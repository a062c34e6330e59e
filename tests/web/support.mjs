// What the browser tests and the web report share: a static server for the site, a page in
// Debian's headless Chromium (WebGL through SwiftShader), the native command line, and pictures
// as raw RGB.
import { chromium } from "playwright-core";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import http from "node:http";
import os from "node:os";
import path from "node:path";

/** The folders and programs the tests use (cargo xtask web test sets them). */
export const env = {
  site: process.env.RAYTRACER_WEB_SITE ?? "target/web",
  raytracer: process.env.RAYTRACER_BIN ?? "target/release/raytracer",
  chromium: process.env.RAYTRACER_CHROMIUM ?? "/usr/bin/chromium",
  scenes: process.env.RAYTRACER_SCENES ?? "scenes",
};

const types = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript",
  ".wasm": "application/wasm",
  ".txt": "text/plain; charset=utf-8",
};

/** Serves `root` on 127.0.0.1 (a free port); `extra` maps a path to a folder served under it. */
export async function serve(root, extra = {}) {
  const server = http.createServer((request, response) => {
    const url = new URL(request.url, "http://localhost");
    let file = path.join(root, decodeURIComponent(url.pathname));
    for (const [prefix, folder] of Object.entries(extra)) {
      if (url.pathname.startsWith(prefix)) {
        file = path.join(folder, decodeURIComponent(url.pathname.slice(prefix.length)));
      }
    }
    if (url.pathname === "/") file = path.join(root, "index.html");
    fs.readFile(file, (error, bytes) => {
      if (error) {
        response.writeHead(404).end("not found");
        return;
      }
      response.writeHead(200, { "content-type": types[path.extname(file)] ?? "application/octet-stream" });
      response.end(bytes);
    });
  });
  await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
  return { server, url: `http://127.0.0.1:${server.address().port}/` };
}

/** Headless Chromium, WebGL 2 through SwiftShader. */
export function launch() {
  return chromium.launch({
    executablePath: env.chromium,
    args: ["--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--no-sandbox"],
  });
}

/**
 * Opens `url` in a fresh page of `browser` and waits for the viewer's handle; `errors` collects
 * console errors and uncaught exceptions.
 */
export async function openViewer(browser, url, viewport = { width: 1280, height: 720 }) {
  const context = await browser.newContext({ viewport, acceptDownloads: true });
  const page = await context.newPage();
  const errors = [];
  page.on("console", (message) => {
    if (message.type() === "error") errors.push(message.text());
  });
  page.on("pageerror", (error) => errors.push(error.message));
  const started = Date.now();
  await page.goto(url);
  await page.waitForFunction(() => window.raytracer !== undefined, null, { timeout: 60_000 });
  return { page, context, errors, started };
}

/** Waits until the viewer shows the current view, nothing pending. */
export async function settled(page, timeout = 60_000) {
  await page.waitForFunction(() => window.raytracer.settled(), null, { timeout, polling: 50 });
}

/** Runs the native command line in `cwd`. */
export function raytracer(args, cwd) {
  return execFileSync(path.resolve(env.raytracer), args, { cwd, stdio: ["ignore", "pipe", "pipe"] });
}

/** A fresh temporary folder. */
export function temporaryFolder() {
  return fs.mkdtempSync(path.join(os.tmpdir(), "raytracer-web-"));
}

/** A TGA file as `{ width, height, rgb }`, top row first. */
export function readTga(file) {
  const bytes = fs.readFileSync(file);
  const idLength = bytes[0];
  const width = bytes.readUInt16LE(12);
  const height = bytes.readUInt16LE(14);
  const topFirst = (bytes[17] & 0x20) !== 0;
  const pixels = bytes.subarray(18 + idLength);
  const rgb = Buffer.alloc(width * height * 3);
  for (let row = 0; row < height; row++) {
    const from = topFirst ? row : height - 1 - row;
    for (let x = 0; x < width; x++) {
      const s = (from * width + x) * 3;
      const d = (row * width + x) * 3;
      rgb[d] = pixels[s + 2];
      rgb[d + 1] = pixels[s + 1];
      rgb[d + 2] = pixels[s];
    }
  }
  return { width, height, rgb };
}

/** A PNG screenshot as `{ width, height, rgb }` (ImageMagick decodes it). */
export function pngToRgb(png) {
  const size = execFileSync("convert", ["png:-", "-format", "%w %h", "info:"], { input: png })
    .toString()
    .trim()
    .split(" ")
    .map(Number);
  const rgb = execFileSync("convert", ["png:-", "-depth", "8", "rgb:-"], {
    input: png,
    maxBuffer: 1 << 28,
  });
  return { width: size[0], height: size[1], rgb };
}

/**
 * Where `picture` appears, pixel for pixel, in `screen` (`{x, y}` of its top-left corner), or
 * null. Pixels where `ignore(index)` is true are not compared.
 */
export function findIn(screen, picture, ignore = () => false) {
  const { width: W, height: H } = screen;
  const { width: w, height: h } = picture;
  const at = (img, width, x, y) => (y * width + x) * 3;
  // The first compared pixel, to find candidates quickly.
  let first = 0;
  while (first < w * h && ignore(first)) first++;
  const fx = first % w;
  const fy = Math.floor(first / w);
  const p0 = at(picture, w, fx, fy);
  for (let y = 0; y + h <= H; y++) {
    for (let x = 0; x + w <= W; x++) {
      const s0 = at(screen, W, x + fx, y + fy);
      if (
        screen.rgb[s0] !== picture.rgb[p0] ||
        screen.rgb[s0 + 1] !== picture.rgb[p0 + 1] ||
        screen.rgb[s0 + 2] !== picture.rgb[p0 + 2]
      ) {
        continue;
      }
      let same = true;
      for (let i = 0; i < w * h && same; i++) {
        if (ignore(i)) continue;
        const px = i % w;
        const py = Math.floor(i / w);
        const s = at(screen, W, x + px, y + py);
        const p = i * 3;
        same =
          screen.rgb[s] === picture.rgb[p] &&
          screen.rgb[s + 1] === picture.rgb[p + 1] &&
          screen.rgb[s + 2] === picture.rgb[p + 2];
      }
      if (same) return { x, y };
    }
  }
  return null;
}

/** The page's current view as the command line's arguments: `[w, h, dmin, dmax]`. */
export async function viewOf(page) {
  const view = await page.evaluate(() => Array.from(window.raytracer.view()));
  return { width: view[6], height: view[7], depthMin: view[4], depthMax: view[5], centre: view.slice(0, 3) };
}

/** Drops a file named `name` with `bytes` on the page's canvas, as a user's drag and drop does. */
export async function dropFile(page, name, bytes) {
  await dropFiles(page, [[name, bytes]]);
}

/** Drops the files `named` (each `[name, bytes]`) on the page's canvas at once. */
export async function dropFiles(page, named) {
  await page.evaluate(
    (files) => {
      const transfer = new DataTransfer();
      for (const { name, data } of files) {
        transfer.items.add(new File([Uint8Array.from(atob(data), (c) => c.charCodeAt(0))], name));
      }
      const canvas = document.querySelector("canvas");
      for (const type of ["dragenter", "dragover", "drop"]) {
        canvas.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
      }
    },
    named.map(([name, bytes]) => ({ name, data: Buffer.from(bytes).toString("base64") })),
  );
}

/**
 * Drops the file at `url` (on the served site) on the page's canvas, named as the URL's last
 * part: the bytes are fetched by the page, so no script of the test's runs on the page's thread
 * meanwhile (decoding a large file from the test would itself block the page).
 */
export async function dropServedFile(page, url) {
  await page.evaluate(async (url) => {
    const blob = await (await fetch(url)).blob();
    const file = new File([blob], url.split("/").pop());
    const transfer = new DataTransfer();
    transfer.items.add(file);
    const canvas = document.querySelector("canvas");
    for (const type of ["dragenter", "dragover", "drop"]) {
      canvas.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
    }
  }, url);
}

/** The native render of `scene` at the page's view: `{ colour, depth }` as raw RGB. */
export function nativeRender(scene, view) {
  const folder = temporaryFolder();
  raytracer(
    [
      "-input", path.resolve(scene), "-size", String(view.width), String(view.height),
      "-output", "colour.tga", "-depth", String(view.depthMin), String(view.depthMax), "depth.tga",
    ],
    folder,
  );
  return { colour: readTga(path.join(folder, "colour.tga")), depth: readTga(path.join(folder, "depth.tga")) };
}

/** Both native pictures are on screen, pixel for pixel (the depth where a ray hits). */
export async function assertOnScreen(page, native) {
  const screen = pngToRgb(await page.screenshot());
  const colourAt = findIn(screen, native.colour);
  assert.ok(colourAt, "the colour image is on screen, pixel for pixel");
  // The viewer marks pixels no ray hits in a colour of its own; the file has them black.
  const background = native.colour.rgb.subarray(0, 3);
  const noHit = (i) =>
    native.colour.rgb[3 * i] === background[0] &&
    native.colour.rgb[3 * i + 1] === background[1] &&
    native.colour.rgb[3 * i + 2] === background[2];
  const depthAt = findIn(screen, native.depth, noHit);
  assert.ok(depthAt, "the depth image is on screen, pixel for pixel where rays hit");
  assert.ok(depthAt.x > colourAt.x, "depth beside colour");
  return { colourAt, depthAt };
}
