// The wasm boundary by name (wasm/src/schema.h): the C++ side declares each call's options and results once, and
// this module turns that declaration into the call's option writer and result reader. No list of positions or
// array types is kept in JavaScript; a name one side has and the other lacks fails loudly, on the first call.

/**
 * The calls of module instance m by name: call(name) gives {writeOptions, readResults}.
 * writeOptions(values): writes the named values into the module's options block, in the C++ declaration's order,
 * and returns the block's address (the binding's options argument). Each declared name must be present in values
 * (booleans as true/false, arrays with the declared count, an enumeration as one of its names); a key values has
 * and the declaration lacks is an error too (checked on the call's first use: a call site's literal keeps its keys).
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
    const choices = c.options.map(([, , names]) => names ?? null);  // an enumeration: written as the name's index
    const total = counts.reduce((a, b) => a + b, 0);
    if (total > capacity) throw new Error(`rtl-wasm: ${name}'s options need ${total} numbers, the block holds ${capacity}`);
    const scalarNames = c.scalars, arrayNames = c.arrays.map(([n]) => n);
    const arrayTypes = c.arrays.map(([, t]) => globalThis[t]);
    const known = new Set(optionNames);
    let keysChecked = false;

    // The generic writer: also the one that names what is wrong when the generated one (below) reports a problem.
    function writeChecked(values) {
      const H = m.HEAPF64;  // read per call: memory growth replaces the buffer
      let k = optionsAt;
      for (let i = 0; i < optionNames.length; i++) {
        const v = values[optionNames[i]];
        if (choices[i]) {
          const at = choices[i].indexOf(v);
          if (at < 0) throw new Error(`rtl-wasm: ${name}: option ${optionNames[i]} ${v} is none of ${choices[i].join(', ')}`);
          H[k++] = at;
        } else if (counts[i] === 1) {
          if (typeof v !== 'number' && typeof v !== 'boolean') throw new Error(`rtl-wasm: ${name}: option ${optionNames[i]} not given`);
          H[k++] = +v;
        } else {
          for (let j = 0; j < counts[i]; j++) H[k++] = v[j];
        }
      }
      // Each call site passes one object literal, the same keys every time: checked on the first call only.
      if (!keysChecked) {
        for (const key in values) if (!known.has(key)) throw new Error(`rtl-wasm: ${name}: the module declares no option ${key}`);
        keysChecked = true;
      }
      return schema.optionsBlock;
    }

    // The declaration as straight-line code (object literals and property names known to the engine): the loops
    // over names above, with a keyed load or store per field, cost ~0.3-0.5 us more per call. Emscripten's embind
    // glue builds its invokers the same way (new Function), so this asks nothing more of the page's CSP.
    const { writeFast, readFast } = generate(optionNames, counts, choices, scalarNames, arrayNames);

    function writeOptions(values) {
      if (!keysChecked || !writeFast(m.HEAPF64, optionsAt, values, choices)) writeChecked(values);
      return schema.optionsBlock;
    }

    function readResults(r, view = false) {
      const traced = typeof r === 'object';
      const H = m.HEAPF64;
      const k = (traced ? r.out : r) / 8;
      if (H[k] !== scalarNames.length) throw new Error(`rtl-wasm: ${name} returned ${H[k]} scalars, its schema declares ${scalarNames.length}`);
      const A = H[k + 1 + scalarNames.length];
      if (A !== arrayNames.length) throw new Error(`rtl-wasm: ${name} returned ${A} arrays, its schema declares ${arrayNames.length}`);
      // one ArrayBuffer per copied array: one shared large buffer faulted its pages in on every call
      const out = readFast(H, k, H.buffer, view, arrayTypes);
      out.trace = traced ? r.trace : undefined;
      return out;
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

// The straight-line writer and reader of one declaration. Names come from the module's own declaration and are
// checked to be identifiers before they are written into code.
function generate(optionNames, counts, choices, scalarNames, arrayNames) {
  for (const n of [...optionNames, ...scalarNames, ...arrayNames])
    if (!/^[A-Za-z_$][\w$]*$/.test(n)) throw new Error(`rtl-wasm: the module declares the name ${JSON.stringify(n)}, not an identifier`);
  // writeFast(H, k, v, C): true when every value was of the declared kind (else the caller writes them again with
  // the checking writer, which throws the message).
  let w = 'let x;\n';
  let at = 0;
  optionNames.forEach((n, i) => {
    w += `x = v.${n};\n`;
    if (choices[i]) w += `x = C[${i}].indexOf(x); if (x < 0) return false; H[k + ${at++}] = x;\n`;
    else if (counts[i] === 1) w += `if (typeof x !== 'number' && typeof x !== 'boolean') return false; H[k + ${at++}] = +x;\n`;
    else {
      w += 'if (x == null) return false;\n';
      for (let j = 0; j < counts[i]; j++) w += `H[k + ${at++}] = x[${j}];\n`;
    }
  });
  w += 'return true;';
  // readFast(H, k, buf, view, T): {scalars, arrays} of the block at index k (counts already checked).
  let r = '';
  const a0 = k0(scalarNames.length);
  arrayNames.forEach((n, i) => { r += `const a${i} = new T[${i}](buf, H[k + ${a0 + 2 * i}], H[k + ${a0 + 2 * i + 1}]);\n`; });
  r += `return { scalars: { ${scalarNames.map((n, i) => `${n}: H[k + ${1 + i}]`).join(', ')} }, ` +
    `arrays: { ${arrayNames.map((n, i) => `${n}: view ? a${i} : a${i}.slice()`).join(', ')} }, trace: undefined };`;
  return {
    writeFast: /** @type {(H: Float64Array, k: number, v: any, C: any[]) => boolean} */ (new Function('H', 'k', 'v', 'C', w)),
    readFast: /** @type {(H: Float64Array, k: number, buf: ArrayBufferLike, view: boolean, T: any[]) => {scalars: Record<string, number>, arrays: Record<string, any>, trace: any}} */ (new Function('H', 'k', 'buf', 'view', 'T', r)),
  };
}

// Index (in doubles, from the block's start) of the first array's address: [S, scalars..., A, address, length...].
function k0(scalarCount) {
  return 2 + scalarCount;
}
