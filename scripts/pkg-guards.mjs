// Patches the JavaScript wasm-bindgen wrote for each part (scripts/build-pkg.sh runs it once per
// fresh `<part>.js`) so that two first-day mistakes throw a typed error saying what went wrong
// (issue 26, point 4), instead of wasm-bindgen's `Error: null pointer passed to rust` and
// `TypeError: Cannot read properties of undefined (reading 'gospa')`:
// - a call before `init()` (browser entry) throws `Error: fisst/<part>: call \`await init()\`
//   first …`: the module's `wasm` starts as a Proxy that throws on any use, until init replaces it;
// - a method (or `free()`) of an object already freed throws `TypeError: <Class> was freed …`.
// It also rewrites the end of each part's `.d.ts` (issue 26, point 3) so that the declarations
// check under `strict` with `lib: ["ES2022"]` alone and no `skipLibCheck`: `InitInput`,
// `SyncInitInput` and `InitOutput` name the platform's types (`Response`, `URL`,
// `WebAssembly.Module`, …) only through `typeof globalThis` (so they are precise where the DOM or
// Node types are loaded and absent where not), `InitOutput` lists the memory only (not the
// module's internal exports), and `[Symbol.dispose]` (ES2024's explicit resource management, a
// type error under ES2022) is left out of the classes: call `free()`.
// The patterns are those of wasm-bindgen 0.2.130 (pinned); a pattern not found fails the build.
import { readFileSync, writeFileSync } from 'node:fs';

const MARK = '// fisst: guards (scripts/pkg-guards.mjs)';

export function guard(source, part) {
  if (source.includes(MARK)) return source;
  const must = (re, what) => {
    if (!re.test(source)) throw new Error(`pkg-guards: ${part}.js has no ${what}: wasm-bindgen's output changed`);
  };
  must(/^let wasmModule, wasmInstance, wasm;$/m, '`let wasmModule, wasmInstance, wasm;`');
  must(/if \(wasm !== undefined\) return wasm;/, '`if (wasm !== undefined) return wasm;`');
  let out = source
    .replace(
      /^let wasmModule, wasmInstance, wasm;$/m,
      `${MARK}
const __fisst_uninit = new Proxy({}, {
    get() {
        throw new Error('fisst/${part}: call \`await init()\` first (in a browser, \`import init, * as fisst from "fisst"; await init();\`); Node\\'s entry needs none');
    },
});
function __fisst_live(obj, name) {
    if (!obj.__wbg_ptr) throw new TypeError(\`\${name} was freed (free() was called on it): make a new \${name}\`);
    return obj.__wbg_ptr;
}
let wasmModule, wasmInstance, wasm = __fisst_uninit;`,
    )
    .replaceAll('if (wasm !== undefined) return wasm;', 'if (wasm !== __fisst_uninit) return wasm;');
  // Each exported class: methods pass `this.__wbg_ptr`; free() takes it through __destroy_into_raw.
  out = out.replace(/^export class (\w+) \{\n([\s\S]*?)^\}\n/gm, (whole, name, body) => {
    const guarded = body
      .replaceAll('(this.__wbg_ptr', `(__fisst_live(this, '${name}')`)
      .replace(/^( +)free\(\) \{\n/m, (m, indent) => `${m}${indent}    __fisst_live(this, '${name}');\n`);
    return `export class ${name} {\n${guarded}}\n`;
  });
  return out;
}

const PLATFORM = `${MARK}
/** A type of the platform (DOM, Node), or \`never\` where the compilation has no such type. */
type Platform<K extends string> = typeof globalThis extends { [P in K]: { prototype: infer T } } ? T : never;
/** \`WebAssembly.Module\` / \`WebAssembly.Memory\` where the platform's types are loaded. */
type WasmType<K extends string> = typeof globalThis extends { WebAssembly: { [P in K]: { prototype: infer T } } } ? T : never;

/** The part's \`.wasm\`: a URL (string or \`URL\`), a \`Request\` or \`Response\`, its bytes, or a compiled module. */
export type InitInput = string | Platform<'URL'> | Platform<'Request'> | Platform<'Response'> | ArrayBuffer | ArrayBufferView | WasmType<'Module'>;

/** What \`init()\` resolves to: the part's instantiated module (its memory). */
export interface InitOutput {
    readonly memory: WasmType<'Memory'>;
}

/** The part's \`.wasm\` for \`initSync\`: its bytes or a compiled module. */
export type SyncInitInput = ArrayBuffer | ArrayBufferView | WasmType<'Module'>;
`;

export function declarations(source, part) {
  if (source.includes(MARK)) return source;
  const start = source.indexOf('export type InitInput =');
  const sync = source.indexOf('export type SyncInitInput =');
  const after = source.indexOf('\n', sync);
  if (start < 0 || sync < start) {
    throw new Error(`pkg-guards: ${part}.d.ts does not end as wasm-bindgen 0.2.130 writes it`);
  }
  return (source.slice(0, start) + PLATFORM + source.slice(after + 1)).replace(/^ +\[Symbol\.dispose\]\(\): void;\n/gm, '');
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const [dir, ...parts] = process.argv.slice(2);
  for (const part of parts) {
    const file = `${dir}/${part}.js`;
    writeFileSync(file, guard(readFileSync(file, 'utf8'), part));
    const dts = `${dir}/${part}.d.ts`;
    writeFileSync(dts, declarations(readFileSync(dts, 'utf8'), part));
  }
}
