// The shader editor's refusal of loops a page cannot bound (common/platform/web/editor.js,
// T10Editor.unboundedLoops; issue 52, item 6: a shader that could hang the GPU is refused with its line,
// never run). Run by node: node editor_loops_test.js EDITOR.JS; exit 0 when every case gives the lines
// expected, 1 with each difference printed.
// It can fail: each refused case names the line it must be refused at (a checker that refused nothing,
// or everything, or at the wrong line, fails), and the accepted cases (the bounded loops a blur would
// write, "for" inside a name, a loop in a comment) fail a checker that refuses too much.
"use strict";
global.window = {};
require(require("path").resolve(process.argv[2]));
const unboundedLoops = window.T10Editor.unboundedLoops;

const cases = [  // [what, source, the lines refused]
  ["no loop", "void main() { float fY = 1.0; }", []],
  ["a fixed count", "void main() {\n  for (int i = 0; i < 5; ++i) { fY += 1.0; }\n}", []],
  ["counting down", "for (int i = 4; i >= 0; i--) fY++;", []],
  ["a blur's taps", "for (int i = -2; i <= 2; i += 1) { }", []],
  ["two loops one after the other", "for (int i = 0; i < 1000; ++i) { }\nfor (int j = 0; j < 1000; ++j) { }", []],
  ["nested within the budget", "for (int i = 0; i < 30; ++i) {\n  for (int j = 0; j < 30; ++j) { }\n}", []],
  ["for and while inside names and comments", "float forward, format; // while (true)\n/* do { } */", []],
  ["a while loop", "float a;\n\n  while (true) { }", [3]],
  ["a do loop", "do {\n} while (fY < 1.0);", [1, 2]],
  ["a bound from a variable", "\nfor (int i = 0; i < n; ++i) { }", [2]],
  ["too many iterations", "for (int i = 0; i < 100000; ++i) { }", [1]],
  ["counting away from the bound", "for (int i = 0; i < 10; --i) { }", [1]],
  ["a float counter", "for (float f = 0.0; f < 1.0; f += 0.1) { }", [1]],
  ["the counter changed in the body", "for (int i = 0; i < 5; ++i) {\n  i = 0;\n}", [1]],
  ["nested past the budget", "for (int i = 0; i < 100; ++i) {\n  for (int j = 0; j < 100; ++j) { }\n}", [2]],
  ["nested without braces", "for (int i = 0; i < 100; ++i)\n  for (int j = 0; j < 100; ++j) fY++;", [2]],
  ["a loop spelt by token pasting", "#define LOOP(a, b) a ## b\nLOOP(wh, ile) (true) { }", [1]],
];

let failures = 0;
for (const [what, source, lines] of cases) {
  const found = unboundedLoops(source).map((e) => e.line);
  const ok = JSON.stringify(found) === JSON.stringify(lines);
  if (!ok) failures++;
  console.log(`${ok ? "ok  " : "FAIL"} ${what}: refused at ${JSON.stringify(found)}${ok ? "" : `, expected ${JSON.stringify(lines)}`}`);
}
console.log(`${cases.length - failures} of ${cases.length} cases as expected`);
process.exit(failures ? 1 : 0);
