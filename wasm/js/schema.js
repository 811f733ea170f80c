// The wasm boundary by name (wasm/src/schema.h): the C++ side declares each call's options and results once, and
// this module turns that declaration into the call's option writer and result reader. No list of positions or
// array types is kept in JavaScript; a name one side has and the other lacks fails loudly, on the first call.

/**
 * The calls of module instance m by name: call(name) gives {writeOptions, readResults}.
 * writeOptions(values): writes the named values into the module's options block, in the C++ declaration's order,
 * and returns the block's address (the binding's options argument). Each declared name must be present in values
 * (booleans as true/false, arrays with the declared count); a key values has and the declaration lacks is an
 * error too.
 * readResults(r, view): a ResultBlock (one number, its address; when traced, {out: address, trace}) as
 * {scalars: {name: number}, arrays: {name: typed array}, trace}: each array copied out of wasm memory, or with
 * view the typed array on the block itself (no copy; valid until the next call that fills or frees the block).
 * Read right after the call: the next call reuses the block.
 */
export function boundaryOf(m) {
  const schema = m.boundarySchema();
  const optionsAt = schema.optionsBlock / 8, capacity = schema.optionsCapacity;
  const cache = new Map();

  function compile(name) {
    const c = schema.calls[name];
    if (!c) throw new Error(`rtl-wasm: the module declares no call "${name}"`);
    const optionNames = c.options.map(([n]) => n), counts = c.options.map(([, k]) => k);
    const total = counts.reduce((a, b) => a + b, 0);
    if (total > capacity) throw new Error(`rtl-wasm: ${name}'s options need ${total} numbers, the block holds ${capacity}`);
    const scalarNames = c.scalars, arrayNames = c.arrays.map(([n]) => n);
    const arrayTypes = c.arrays.map(([, t]) => globalThis[t]);
    const known = new Set(optionNames);

    function writeOptions(values) {
      const H = m.HEAPF64;  // read per call: memory growth replaces the buffer
      let k = optionsAt;
      for (let i = 0; i < optionNames.length; i++) {
        const v = values[optionNames[i]];
        if (counts[i] === 1) {
          if (typeof v !== 'number' && typeof v !== 'boolean') throw new Error(`rtl-wasm: ${name}: option ${optionNames[i]} not given`);
          H[k++] = +v;
        } else {
          for (let j = 0; j < counts[i]; j++) H[k++] = v[j];
        }
      }
      for (const key in values) if (!known.has(key)) throw new Error(`rtl-wasm: ${name}: the module declares no option ${key}`);
      return schema.optionsBlock;
    }

    function readResults(r, view = false) {
      const traced = typeof r === 'object';
      const H = m.HEAPF64, buf = H.buffer;
      let k = (traced ? r.out : r) / 8;
      const S = H[k++];
      if (S !== scalarNames.length) throw new Error(`rtl-wasm: ${name} returned ${S} scalars, its schema declares ${scalarNames.length}`);
      /** @type {Record<string, number>} */
      const scalars = {};
      for (let i = 0; i < S; i++) scalars[scalarNames[i]] = H[k++];
      const A = H[k++];
      if (A !== arrayNames.length) throw new Error(`rtl-wasm: ${name} returned ${A} arrays, its schema declares ${arrayNames.length}`);
      /** @type {Record<string, any>} */
      const arrays = {};
      for (let i = 0; i < A; i++, k += 2) {
        const a = new arrayTypes[i](buf, H[k], H[k + 1]);
        arrays[arrayNames[i]] = view ? a : a.slice();
      }
      return { scalars, arrays, trace: traced ? r.trace : undefined };
    }
    return { writeOptions, readResults };
  }

  /** The writer and reader of the call `name` (compiled once per instance). */
  function call(name) {
    let c = cache.get(name);
    if (!c) cache.set(name, c = compile(name));
    return c;
  }
  return { call };
}
