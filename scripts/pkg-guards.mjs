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
// type error under ES2022) is left out of the classes: call `free()`. Each part's `.d.ts` then
// keeps only the names its functions and classes reach (`ownNames`).
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
  const patched = (source.slice(0, start) + PLATFORM + source.slice(after + 1)).replace(/^ +\[Symbol\.dispose\]\(\): void;\n/gm, '');
  return ownNames(patched);
}

/**
 * The top-level statements of a declaration file, each with the JSDoc comment right before
 * it, and the text between them (other comments, blank lines) as `filler`.
 */
export function statements(source) {
  const out = [];
  let i = 0;
  let filler = '';
  let doc = '';
  const flush = () => {
    out.push({ filler: filler + doc });
    filler = '';
    doc = '';
  };
  while (i < source.length) {
    const ch = source[i];
    if (/\s/.test(ch)) {
      (doc ? (doc += ch) : (filler += ch));
      i += 1;
    } else if (source.startsWith('/*', i)) {
      const end = source.indexOf('*/', i) + 2;
      if (doc) flush();
      if (source.startsWith('/**', i)) doc = source.slice(i, end);
      else filler += source.slice(i, end);
      i = end;
    } else if (source.startsWith('//', i)) {
      const end = source.indexOf('\n', i);
      if (doc) flush();
      filler += source.slice(i, end);
      i = end;
    } else {
      // a statement: to `;` at depth 0, or to the `}` closing an interface/class body
      const from = i;
      let depth = 0;
      let body = false;
      for (; i < source.length; i += 1) {
        const c = source[i];
        if (source.startsWith('/*', i)) {
          i = source.indexOf('*/', i) + 1;
        } else if (source.startsWith('//', i)) {
          i = source.indexOf('\n', i) - 1;
        } else if (c === '"' || c === "'" || c === '`') {
          i = source.indexOf(c, i + 1);
        } else if ('{[('.includes(c)) {
          if (c === '{' && depth === 0) body = true;
          depth += 1;
        } else if ('}])'.includes(c)) {
          depth -= 1;
          if (depth === 0 && c === '}' && body && /^(export\s+)?(declare\s+)?(interface|class|namespace|enum)\b/.test(source.slice(from, i))) {
            i += 1;
            break;
          }
        } else if (c === ';' && depth === 0) {
          i += 1;
          break;
        }
      }
      const text = source.slice(from, i);
      const head = /^(?:export\s+)?(?:declare\s+)?(?:default\s+)?(function|class|interface|type|const|let|var|enum|namespace)\s+([A-Za-z_$][\w$]*)/.exec(text);
      out.push({ filler, doc, text, kind: head?.[1] ?? 'other', name: head?.[2] });
      filler = '';
      doc = '';
    }
  }
  out.push({ filler: filler + doc });
  return out;
}

/** The identifiers a statement's code (not its comments or strings) names. */
function namesIn(text) {
  const code = text.replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/.*$/gm, ' ').replace(/(["'`])(?:(?!\1).)*\1/g, ' ');
  return new Set(code.match(/[A-Za-z_$][\w$]*/g) ?? []);
}

/**
 * Each part's declarations hold only its own names (issue 26, point 3): a part's module
 * carries every shared type of the bindings (tsify declares them wherever they are compiled),
 * so the types its functions and classes do not reach are left out. Another name for a reached
 * type (`export type ActionOut = Action;`, a contract name of the part) stays. An interface
 * merged into a class (method overloads, declared by the bindings before the class) is placed
 * after the class, so that its signatures are tried first.
 */
export function ownNames(source) {
  const st = statements(source);
  const decls = st.filter((s) => s.text !== undefined);
  const typeKinds = new Set(['type', 'interface']);
  const classes = new Set(decls.filter((s) => s.kind === 'class').map((s) => s.name));
  const refs = new Map();
  for (const s of decls) {
    if (!s.name) continue;
    const set = refs.get(s.name) ?? new Set();
    for (const n of namesIn(s.text)) if (n !== s.name) set.add(n);
    refs.set(s.name, set);
  }
  const roots = decls
    .filter((s) => !typeKinds.has(s.kind) || classes.has(s.name) || ['InitInput', 'InitOutput', 'SyncInitInput'].includes(s.name))
    .map((s) => s.name)
    .filter(Boolean);
  const reached = new Set(roots);
  const queue = [...roots];
  while (queue.length) {
    for (const n of refs.get(queue.pop()) ?? []) {
      if (refs.has(n) && !reached.has(n)) {
        reached.add(n);
        queue.push(n);
      }
    }
  }
  const keep = (s) => {
    if (!typeKinds.has(s.kind) || !s.name || reached.has(s.name)) return true;
    // `export type X = Y;`, Y reached: another name the part gives its own type
    const alias = /=\s*([A-Za-z_$][\w$]*)\s*;$/.exec(s.text);
    return s.kind === 'type' && alias !== null && reached.has(alias[1]);
  };
  const merged = new Map();
  const kept = [];
  for (const s of st) {
    if (s.text === undefined) kept.push(s);
    else if (s.kind === 'interface' && classes.has(s.name)) merged.set(s.name, s);
    else if (keep(s)) kept.push(s);
    else kept.push({ filler: s.filler });
  }
  let out = '';
  for (const s of kept) {
    out += s.filler + (s.doc ?? '') + (s.text ?? '');
    const m = s.kind === 'class' && merged.get(s.name);
    if (m) out += `\n${m.doc ? `${m.doc}\n` : ''}${m.text}`;
  }
  return out.replace(/\n{4,}/g, '\n\n\n');
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
