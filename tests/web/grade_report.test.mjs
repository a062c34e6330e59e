// The grading report (`raytracer grade`) as a teacher opens it: from the file system, in headless
// Chromium, with no server and no network. A small class is graded with the native binary: an
// exact submission, one with another scene's picture, one missing images, and one whose folder
// is named with HTML. The table and every submission's page load with no console error and no
// dialog, every link and picture resolves, and sorting by a column orders the rows both ways.
import { after, before, test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { pathToFileURL } from "node:url";
import { env, launch } from "./support.mjs";

let browser;
let report;

before(async () => {
  const root = fs.mkdtempSync(path.join(os.tmpdir(), "raytracer-grade-"));
  const assignment = path.resolve(env.scenes, "assignment1.commands");
  const lines = fs
    .readFileSync(assignment, "utf8")
    .split("\n")
    .filter((line) => line.startsWith("raytracer "));
  const submit = (name, keep) => {
    const folder = path.join(root, "submissions", name);
    fs.mkdirSync(folder, { recursive: true });
    lines.forEach((line, index) => {
      if (!keep(index)) return;
      const words = line.split(/\s+/).slice(1);
      words[1] = path.resolve(env.scenes, words[1]);
      execFileSync(path.resolve(env.raytracer), words, { cwd: folder });
    });
    return folder;
  };
  submit("exact", () => true);
  submit("half", (index) => index % 2 === 0);
  submit("<img src=x onerror=alert(1)>", () => true);
  const other = submit("other scene", () => true);
  fs.copyFileSync(path.join(other, "output1_03.tga"), path.join(other, "output1_02.tga"));
  execFileSync(path.resolve(env.raytracer), ["grade", assignment, "submissions", "-o", "report"], {
    cwd: root,
  });
  report = path.join(root, "report");
  browser = await launch();
});

after(async () => {
  await browser?.close();
});

/** Opens a report file; fails on a console error, an uncaught exception or a dialog. */
async function open(file) {
  const page = await browser.newPage();
  const problems = [];
  page.on("console", (message) => {
    if (message.type() === "error") problems.push(message.text());
  });
  page.on("pageerror", (error) => problems.push(String(error)));
  page.on("dialog", (dialog) => {
    problems.push(`dialog: ${dialog.message()}`);
    dialog.dismiss();
  });
  await page.goto(pathToFileURL(file).href);
  await page.waitForLoadState("load");
  return { page, problems };
}

test("the table and every page load with no error, and every link and picture resolves", async () => {
  const pages = [path.join(report, "index.html")];
  const seen = new Set();
  while (pages.length > 0) {
    const file = pages.pop();
    if (seen.has(file)) continue;
    seen.add(file);
    const { page, problems } = await open(file);
    const targets = await page.$$eval("a[href], img[src]", (elements) =>
      elements.map((e) => e.getAttribute("href") ?? e.getAttribute("src")),
    );
    for (const target of targets) {
      const resolved = path.resolve(path.dirname(file), target.split("#")[0]);
      assert.ok(fs.existsSync(resolved), `${path.relative(report, file)}: ${target} does not exist`);
      if (resolved.endsWith(".html")) pages.push(resolved);
    }
    const broken = await page.$$eval("img", (images) =>
      images.filter((i) => !i.complete || i.naturalWidth === 0).map((i) => i.getAttribute("src")),
    );
    assert.deepEqual(broken, [], `${path.relative(report, file)}: pictures that do not load`);
    assert.deepEqual(problems, [], `${path.relative(report, file)}`);
    await page.close();
  }
  // The table and a page per submission.
  assert.equal(seen.size, 1 + 4);
});

test("a folder named with HTML is shown as text", async () => {
  const { page, problems } = await open(path.join(report, "index.html"));
  const names = await page.$$eval("#grades tbody tr td:first-child", (cells) =>
    cells.map((c) => c.textContent),
  );
  assert.ok(names.includes("<img src=x onerror=alert(1)>"), names.join(" | "));
  assert.equal(await page.locator("#grades img").count(), 0);
  assert.deepEqual(problems, []);
  await page.close();
});

test("clicking a column's title sorts the rows by it, again the other way", async () => {
  const { page, problems } = await open(path.join(report, "index.html"));
  const matching = () =>
    page.$$eval("#grades tbody tr", (rows) => rows.map((r) => Number(r.cells[1].dataset.sort)));
  const title = page.locator("#grades thead th", { hasText: "matching" });
  await title.click();
  const up = await matching();
  assert.deepEqual(up, [...up].sort((a, b) => a - b));
  assert.notDeepEqual(up, [...up].reverse(), "the class has different counts");
  await title.click();
  const down = await matching();
  assert.deepEqual(down, [...up].sort((a, b) => b - a));
  const names = () => page.$$eval("#grades tbody tr", (rows) => rows.map((r) => r.cells[0].textContent));
  await page.locator("#grades thead th", { hasText: "submission" }).click();
  const sorted = await names();
  const lower = sorted.map((name) => name.toLowerCase());
  assert.deepEqual(lower, [...lower].sort());
  assert.deepEqual(problems, []);
  await page.close();
});
