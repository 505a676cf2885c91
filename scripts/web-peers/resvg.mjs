// tiny-skia, through resvg, as an external renderer of `aabench compare --web-peers`
// (docs/external.md).
//
//   node resvg.mjs SCENE.svg OUT.png   renders the {svg} aabench writes, writes an 8-bit PNG and
//                                      prints "aabench-time-ms: X", the time of the render alone
//   node resvg.mjs --version           prints the package and its version
//
// @resvg/resvg-js carries resvg (Rust) and its rasterizer tiny-skia, a port of Skia's, as a
// prebuilt binary. The SVG is rendered as resvg renders any file: at its own size (1 user unit
// = 1 px), shape-rendering geometricPrecision (antialiased), no fonts needed (aabench writes
// text as its glyphs' outlines). Its pixels are premultiplied 8-bit RGBA, blended in codes.
import { readFileSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { performance } from "node:perf_hooks";

const require = createRequire(import.meta.url);
const resvgPackage = "@resvg/resvg-js";

function fail(message) {
  process.stderr.write(`resvg.mjs: ${message}\n`);
  process.exit(2);
}

const args = process.argv.slice(2);
if (args[0] === "--version") {
  try {
    require(resvgPackage);  // the native binding, not only its package.json
    const { version } = require(`${resvgPackage}/package.json`);
    process.stdout.write(`${resvgPackage} ${version}\n`);
    process.exit(0);
  } catch (error) {
    fail(String(error.message || error).split("\n")[0]);
  }
}
if (args.length !== 2) fail("usage: node resvg.mjs SCENE.svg OUT.png");

let resvg;
try {
  const { Resvg } = require(resvgPackage);
  const svg = readFileSync(args[0], "utf8");
  resvg = new Resvg(svg, { fitTo: { mode: "original" }, shapeRendering: 2, font: { loadSystemFonts: false } });
} catch (error) {
  fail(`${args[0]}: ${String(error.message || error).split("\n")[0]}`);
}
try {
  resvg.render();  // warm-up: the first render pays for the library's first use
  const start = performance.now();
  const image = resvg.render();
  const ms = performance.now() - start;
  writeFileSync(args[1], image.asPng());
  process.stdout.write(`aabench-time-ms: ${ms}\n`);
} catch (error) {
  fail(String(error.message || error).split("\n")[0]);
}
