// The colours of the package's drawings (toSvg, toTikz): cluster k is drawn in palette[k % palette.length] and
// points without a cluster in unlabelledColour, as CSS hex colours. The Okabe-Ito colour-blind safe set plus darker
// companions; no pure red (kept for fitted lines). The C++ side that draws the pictures (wasm/src/scan_drawing.h)
// holds the same list; tests/js/draw.test.mjs checks the drawings against this one.

/** @type {readonly string[]} */
export const palette = Object.freeze(['#0072B2', '#E69F00', '#009E73', '#D55E00', '#CC79A7', '#56B4E9', '#8C6D1F',
  '#1B7837', '#762A83', '#332288']);

/** The colour of points without a cluster (label -1). */
export const unlabelledColour = '#808080';
