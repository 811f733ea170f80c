// A consumer app as a web developer writes it: a bare import of the installed package, bundled by `vite build`.
// It fits a line to four points with a known answer, triggers one error, segments and vectorizes an L-shaped wall and
// draws with the SVG exporter (after loading the package's extras module), then publishes the outcome on window.__result (and in the page) for the browser test.
import init from 'rtl-wasm';

// Points at t = -3, -1, 1, 3 along the direction u = (2, 1)/sqrt(5) through (1, 1.5), pushed off the line by
// +d, -d, -d, +d along the normal: the offsets are uncorrelated with t, so the TLS line is exactly the original
// line and the RMS orthogonal distance is exactly d.
const s5 = Math.sqrt(5);
const u = [2 / s5, 1 / s5];
const n = [-1 / s5, 2 / s5];
const d = 0.05;
const points = new Float64Array([-3, -1, 1, 3].flatMap((t, i) => {
  const o = i === 0 || i === 3 ? d : -d;
  return [1 + t * u[0] + o * n[0], 1.5 + t * u[1] + o * n[1]];
}));

async function main() {
  const rtl = await init();
  const fit = rtl.fitLine(points);
  let error = null;
  try {
    rtl.fitLine(new Float64Array([1, 2]));
  } catch (e) {
    error = { name: e.name, message: e.message };
  }
  const again = rtl.fitLine(points); // the module keeps working after an error
  await rtl.load('extras'); // toSvg is in the package's extras module, fetched on demand
  // The package's SVG exporter draws the points and the fitted line (between the outer points' projections).
  const [c, dir] = [fit.centroid, fit.direction];
  const end = (t) => [c[0] + t * dir[0], c[1] + t * dir[1]];
  const svg = rtl.toSvg({ points, segments: [...end(-3), ...end(3)], title: 'TLS line' }, { width: 400, height: 300 });
  document.getElementById('figure').innerHTML = svg;
  // An L-shaped wall (2 m along x, then 1.5 m along y, 10 cm spacing) and a far point: two clusters, and FTLS
  // turns the L into its two sides meeting at the corner (2, 0).
  const wall = [];
  for (let i = 0; i <= 20; i++) wall.push(i * 0.1, 0);
  for (let i = 1; i <= 15; i++) wall.push(2, i * 0.1);
  const seg = rtl.segment(new Float64Array([...wall, 9, 9]), { lowerBound: 0.2, upperBound: 0.5 });
  const vec = rtl.vectorize(new Float64Array(wall), { method: 'ftls', sigma: 0.01 });
  return {
    clusterSizes: seg.clusters.map((c) => c.indices.length),
    segments: Array.from(vec.segments),
    svgCircles: document.querySelectorAll('#figure svg circle').length,
    svgLines: document.querySelectorAll('#figure svg line').length,
    version: rtl.version,
    normal: Array.from(fit.normal),
    offset: fit.offset,
    rms: fit.rms,
    count: fit.count,
    error,
    againRms: again.rms,
  };
}

main().then(
  (r) => { window.__result = r; },
  (e) => { window.__result = { failure: `${e.name}: ${e.message}` }; },
).finally(() => {
  document.getElementById('out').textContent = JSON.stringify(window.__result, null, 2);
});
