// The expected output of a program written in the convention of the README snippets and of
// docs/recipes/: each `console.log(` line is followed by its expected output as a `// ` comment, on
// the same line (after the code) or on the comment lines right below it (one per printed line).
// Shared by recipes.test.mjs (the recipes against the built package) and first_day.test.mjs
// (the same recipes against the package packed and installed into a fresh project).
import assert from 'node:assert/strict';

/** The expected output lines of a recipe, from the comments after its console.log lines. */
export function expectedOutput(code) {
  const lines = code.split('\n');
  const expected = [];
  lines.forEach((line, i) => {
    const t = line.trim();
    if (!t.includes('console.log(') || t.startsWith('//')) return;
    const cut = t.lastIndexOf(' // ');
    if (cut > t.indexOf('console.log(')) {
      expected.push(t.slice(cut + 4).trim());
      return;
    }
    const below = [];
    for (let j = i + 1; j < lines.length; j++) {
      const m = lines[j].trim().match(/^\/\/ ?(.*)$/);
      if (!m) break;
      below.push(m[1].trim());
    }
    assert.ok(below.length > 0, `line ${i + 1} has a console.log without an expected-output comment: ${t}`);
    expected.push(...below);
  });
  return expected;
}
