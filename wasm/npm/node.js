// Node entry of the npm package `fisst`: instantiates the WebAssembly module synchronously
// from the file beside this one, so `import * as fisst from 'fisst'` needs no init call.
// `init()` is still exported (resolving at once) so browser code runs unchanged in Node.
import { readFileSync } from 'node:fs';
import { initSync } from './fisst_wasm.js';

const output = initSync({ module: readFileSync(new URL('./fisst_wasm_bg.wasm', import.meta.url)) });

export * from './fisst_wasm.js';

/** Already initialised in Node: resolves at once to the module's exports. */
export default async function init() {
  return output;
}
