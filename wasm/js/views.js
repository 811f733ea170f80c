// Reading the C++ side's flat results: parts of one typed array as views, and the flat trace as event objects.

/**
 * The parts of a typed array between consecutive offsets (each offset counts `width` elements) as views on its
 * buffer, made with the constructor: subarray() looks up the species constructor each time, ~2x slower; a slice()
 * per part allocates a backing store each.
 */
export function partViews(array, offsets, width = 1) {
  const Type = array.constructor, buf = array.buffer, base = array.byteOffset, bytes = Type.BYTES_PER_ELEMENT * width;
  const count = Math.max(0, offsets.length - 1), out = new Array(count);
  for (let k = 0; k < count; k++) out[k] = new Type(buf, base + bytes * offsets[k], width * (offsets[k + 1] - offsets[k]));
  return out;
}

/**
 * The C++ side's flat trace (wasm/src/trace_ops.h: names + numbers) as plain objects { kind, field: value, ... },
 * one per event, in order. Field types: 0 number, 1 integer, 2 boolean. The events' shapes are the C++ side's
 * (index.d.ts declares them per function), hence no narrower type here.
 * @returns {any[]}
 */
export function traceEvents(t) {
  const { names, data } = t;
  const out = [];
  for (let i = 0; i < data.length;) {
    const e = { kind: names[data[i]] };
    const fields = data[i + 1];
    i += 2;
    for (let k = 0; k < fields; k++, i += 3) e[names[data[i]]] = data[i + 1] === 2 ? data[i + 2] !== 0 : data[i + 2];
    out.push(e);
  }
  return out;
}
