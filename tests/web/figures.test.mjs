// The figures docs/web.md gives of the page (its report, written by `cargo xtask web report`,
// and copied into docs/browser.md) are those of the site built now: the .wasm's size within
// MOST_DRIFT of the built one, so a build that grows fails here until the report is made again.
import { test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { env } from "./support.mjs";

/** The largest share the .wasm's size in docs/web.md may differ from the built one's. */
const MOST_DRIFT = 0.05;

test("docs/web.md gives the size of the .wasm built now", () => {
  const report = fs.readFileSync("docs/web.md", "utf8");
  const row = report.split("\n").find((line) => line.startsWith("| `raytracer_bg.wasm` |"));
  assert.ok(row, "docs/web.md has the .wasm's row");
  const written = Number(row.split("|")[2].trim().replaceAll(",", ""));
  const built = fs.statSync(path.join(env.site, "raytracer_bg.wasm")).size;
  const drift = Math.abs(written - built) / built;
  assert.ok(
    drift <= MOST_DRIFT,
    `docs/web.md says ${written} bytes, the site built now has ${built} ` +
      `(${(100 * drift).toFixed(1)}% apart): run cargo xtask web report, then cargo xtask report sync`,
  );
});
