// The code bytes of wasm modules by kind, from their function names (a build with
// `wasm-bindgen --keep-debug`; benches/wasm_code_kinds.sh makes one and calls this):
//   node benches/wasm_code_kinds.mjs [--top N] DIR [DIR…]   (DIR holds <part>_bg.wasm for the six parts)
// `--top N` also lists the N largest functions (bytes summed over the six modules, with the
// number of modules holding each and its kind).
// Kinds, by the first rule that matches a function's name: serde (serde, (De)Serialize impls,
// visitors, the binding's de.rs and names.rs, the core's serde_valid), binding (fisst_wasm,
// wasm-bindgen, js-sys, and unnamed glue), numerics (fisst), nalgebra + libm, runtime (core,
// alloc, std, dlmalloc, hashbrown, …); data is the data section. Monomorphised generics count
// where their name says (a core type's Deserialize impl is serde, not numerics).
import { readFileSync } from 'node:fs';

const PARTS = ['bernoulli', 'splitting', 'filters', 'bounds', 'metrics', 'control'];
const KINDS = ['serde', 'binding', 'numerics', 'nalgebra+libm', 'runtime', 'data'];

function kinds(file) {
  const buf = readFileSync(file);
  let p = 8;
  const leb = () => {
    let r = 0;
    let s = 0;
    let b;
    do {
      b = buf[p++];
      r += (b & 0x7f) * 2 ** s;
      s += 7;
    } while (b & 0x80);
    return r;
  };
  let imports = 0;
  const bodies = [];
  const names = new Map();
  let data = 0;
  while (p < buf.length) {
    const id = buf[p++];
    const size = leb();
    const end = p + size;
    if (id === 0) {
      const len = leb();
      const name = buf.subarray(p, p + len).toString();
      p += len;
      while (name === 'name' && p < end) {
        const sub = buf[p++];
        const subEnd = leb() + p;
        if (sub === 1) {
          for (let n = leb(); n > 0; n--) {
            const index = leb();
            const l = leb();
            names.set(index, buf.subarray(p, p + l).toString());
            p += l;
          }
        }
        p = subEnd;
      }
    } else if (id === 2) {
      for (let n = leb(); n > 0; n--) {
        for (let name = 0; name < 2; name++) {
          const len = leb(); // module, then field name (`p += leb()` would read p first)
          p += len;
        }
        const kind = buf[p++];
        if (kind === 0) {
          leb();
          imports++;
        } else if (kind === 1) {
          p++;
          if (buf[p++] & 1) leb();
          leb();
        } else if (kind === 2) {
          if (buf[p++] & 1) leb();
          leb();
        } else {
          p += 2;
        }
      }
    } else if (id === 10) {
      for (let n = leb(), i = 0; i < n; i++) {
        const l = leb();
        bodies.push([imports + i, l]);
        p += l;
      }
    } else if (id === 11) {
      data = size;
    }
    p = end;
  }
  if (names.size === 0) throw new Error(`${file} has no name section: build it with --keep-debug`);
  const out = Object.fromEntries(KINDS.map((k) => [k, 0]));
  out.data = data;
  out.functions = [];
  for (const [index, len] of bodies) {
    const n = names.get(index) ?? '';
    let k;
    if (/serde|Deserializ|Serializ|Visitor|MapAccess|SeqAccess|EnumAccess|VariantAccess|fisst_wasm::(de|names)::/.test(n)) k = 'serde';
    else if (/fisst_wasm|wasm_bindgen|js_sys|__wbg|__wbindgen/.test(n) || !n.includes('::')) k = 'binding';
    else if (/fisst::/.test(n)) k = 'numerics';
    else if (/nalgebra|libm/.test(n)) k = 'nalgebra+libm';
    else k = 'runtime';
    out[k] += len;
    out.functions.push([n, len, k]);
  }
  return out;
}

const args = process.argv.slice(2);
let top = 0;
if (args[0] === '--top') {
  top = Number(args[1]);
  args.splice(0, 2);
}
for (const dir of args) {
  const byName = new Map();
  console.log(`${dir}\n${['part', ...KINDS, 'total'].map((s) => s.padStart(14)).join('')}`);
  const sum = Object.fromEntries(KINDS.map((k) => [k, 0]));
  for (const part of PARTS) {
    const k = kinds(`${dir}/${part}_bg.wasm`);
    for (const key of KINDS) sum[key] += k[key];
    for (const [n, len, kind] of k.functions) {
      const e = byName.get(n) ?? { bytes: 0, modules: 0, kind };
      e.bytes += len;
      e.modules += 1;
      byName.set(n, e);
    }
    const total = KINDS.reduce((a, key) => a + k[key], 0);
    console.log([part, ...KINDS.map((key) => k[key]), total].map((s) => String(s).padStart(14)).join(''));
  }
  const total = KINDS.reduce((a, key) => a + sum[key], 0);
  console.log(['six', ...KINDS.map((key) => sum[key]), total].map((s) => String(s).padStart(14)).join(''));
  const largest = [...byName].sort((a, b) => b[1].bytes - a[1].bytes).slice(0, top);
  for (const [n, e] of largest) {
    console.log(`${String(e.bytes).padStart(9)} ${e.modules} ${e.kind.padEnd(13)} ${n}`);
  }
}
