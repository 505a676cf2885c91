// Skia as an external renderer of `aabench compare --web-peers` (docs/external.md).
//
//   node skia.mjs SCENE.svg OUT.png    draws the {svg} aabench writes, writes an 8-bit PNG and
//                                      prints "aabench-time-ms: X", the time of the draw alone
//   node skia.mjs --version            prints the package and its version
//
// Skia comes from @napi-rs/canvas (a prebuilt Skia inside the npm package): an HTML-canvas API
// on a raster surface. The file is aabench's own SVG (harness/report/scene_svg.cpp): one
// background <rect>, then one <path fill-rule="nonzero" fill="#rrggbb" d="..."/> per shape, in
// order. Each path is filled as a web page would fill it: `ctx.fill(new Path2D(d), "nonzero")`
// with the canvas's default antialiasing, composited source-over in the canvas's 8-bit codes.
import { readFileSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { performance } from "node:perf_hooks";

const require = createRequire(import.meta.url);
const canvasPackage = "@napi-rs/canvas";

function fail(message) {
  process.stderr.write(`skia.mjs: ${message}\n`);
  process.exit(2);
}

const args = process.argv.slice(2);
if (args[0] === "--version") {
  try {
    require(canvasPackage);  // the native binding, not only its package.json
    const { version } = require(`${canvasPackage}/package.json`);
    process.stdout.write(`${canvasPackage} ${version}\n`);
    process.exit(0);
  } catch (error) {
    fail(String(error.message || error).split("\n")[0]);
  }
}
if (args.length !== 2) fail("usage: node skia.mjs SCENE.svg OUT.png");

let createCanvas, Path2D, svg;
try {
  ({ createCanvas, Path2D } = require(canvasPackage));
  svg = readFileSync(args[0], "utf8");
} catch (error) {
  fail(String(error.message || error).split("\n")[0]);
}

const size = /<svg[^>]*\bwidth="(\d+)"[^>]*\bheight="(\d+)"/.exec(svg);
if (!size) fail(`${args[0]}: no <svg width=".." height=".."> element`);
const width = Number(size[1]);
const height = Number(size[2]);
const background = /<rect[^>]*\bfill="(#[0-9a-fA-F]{6})"/.exec(svg);
if (!background) fail(`${args[0]}: no background <rect fill="#rrggbb">`);
const paths = [];
for (const m of svg.matchAll(/<path\b([^>]*)\/>/g)) {
  const fill = /\bfill="(#[0-9a-fA-F]{6})"/.exec(m[1]);
  const d = /\bd="([^"]*)"/.exec(m[1]);
  const rule = /\bfill-rule="(nonzero|evenodd)"/.exec(m[1]);
  if (!fill || !d) fail(`${args[0]}: a <path> without fill="#rrggbb" or d="..."`);
  paths.push({ fill: fill[1], d: d[1], rule: rule ? rule[1] : "nonzero" });
}

let canvas, ctx;
try {
  canvas = createCanvas(width, height);
  ctx = canvas.getContext("2d");
  // The path data parsed before the clock, as resvg.mjs parses its file before it: the timed
  // draw is the fills alone.
  for (const p of paths) p.path = new Path2D(p.d);
} catch (error) {
  fail(`${args[0]}: ${String(error.message || error).split("\n")[0]}`);
}
function draw() {
  ctx.fillStyle = background[1];
  ctx.fillRect(0, 0, width, height);
  for (const p of paths) {
    ctx.fillStyle = p.fill;
    ctx.fill(p.path, p.rule);
  }
  // Reading one pixel makes the surface finish every pending draw before the clock stops.
  ctx.getImageData(0, 0, 1, 1);
}
try {
  draw();  // warm-up: the first draw pays for the library's and the JIT's first use
  const start = performance.now();
  draw();
  const ms = performance.now() - start;
  writeFileSync(args[1], canvas.toBuffer("image/png"));
  process.stdout.write(`aabench-time-ms: ${ms}\n`);
} catch (error) {
  fail(String(error.message || error).split("\n")[0]);
}
