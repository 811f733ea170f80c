// Lesson: frames and the transformation tree. A real scan is measured in the sensor frame; the sensor sits on the
// robot (mount offset and angle), the robot sits in the map (the log's corrected pose). The package's TfTree holds
// map -> robot -> sensor and moves the points; every number here comes from it.

// Intel Research Lab, scan 20: the robot has turned and moved away from the log's origin (pose about (9.0, -0.7) m,
// heading -45 degrees), so each transformation visibly moves the points. The Intel log's points are already in the
// robot frame (the laser at the robot's origin): mount 0 is the log's truth, any other mount misplaces the walls
// against the log's other scans, drawn grey in the map.
export const EXCERPT = Object.freeze({ dataset: 'intel', scan: 20, neighbours: [16, 17, 18, 19, 21, 22, 23, 24] });
import { Scene } from '../figure.js';
import { note, numberField } from './ui.js';

const STEPS = ['sensor', 'mount', 'pose', 'chain'];
const FRAME_COLOURS = { map: '#000000', robot: '#0072B2', sensor: '#D55E00' };
const f2 = (v) => (Number.isFinite(v) ? v.toFixed(2) : '–');
const deg = (r) => `${(r * 180 / Math.PI).toFixed(1)}°`;

// TfTree.insert takes the transformation from the parent's coordinates to the child's, i.e. the inverse of the
// child's pose in the parent. The package inverts it: in a scratch tree holding the pose as parent -> child, the
// tree's tf(child, parent) is the pose's inverse.
function inverseOf(rtl, pose) {
  const t = new rtl.TfTree('a', { dim: 2 });
  try {
    t.insert('b', 'a', { angle: pose.angle, translation: pose.translation });
    const inv = t.tf('b', 'a');
    return { angle: Math.atan2(inv.rotation[2], inv.rotation[0]), translation: [inv.translation[0], inv.translation[1]] };
  } finally {
    t.dispose();
  }
}

export function buildTree(rtl, pose, mount) {
  const tree = new rtl.TfTree('map', { dim: 2 });
  tree.insert('robot', 'map', inverseOf(rtl, { angle: pose.theta, translation: [pose.x, pose.y] }));
  tree.insert('sensor', 'robot', inverseOf(rtl, { angle: mount.angle, translation: [mount.x, mount.y] }));
  return tree;
}

export default {
  id: 'tf-tree',
  title: 'Transformation tree',
  summary: 'Sensor → robot → map: a real scan moved through the package\'s TfTree, one frame at a time.',
  async create(host) {
    const scans = await host.data.load(EXCERPT.dataset);
    const scan = scans[EXCERPT.scan];
    const measured = Array.from(scan.points);        // treated as the sensor's measurement
    const controls = host.controls;
    const field = (key, label, opts) => numberField(controls, { key, label, value: 0, onInput: () => host.onParamsChanged(), ...opts });
    const mx = field('mountX', 'Sensor mount x', { min: -5, max: 5, step: 0.05, kind: 'number', unit: 'm' });
    const my = field('mountY', 'Sensor mount y', { min: -5, max: 5, step: 0.05, kind: 'number', unit: 'm' });
    const ma = field('mountAngle', 'Sensor mount angle', { min: -30, max: 30, step: 1, unit: '°', digits: 0 });
    note(controls, `Intel scan ${EXCERPT.scan}; grey: scans ${EXCERPT.neighbours[0]}–${EXCERPT.neighbours.at(-1)} placed by their own poses. ` +
      'The log\'s laser sits at the robot\'s origin, so mount 0 makes the walls agree; any other mount is a miscalibration.');
    let mount = { x: 0, y: 0, angle: 0 }, mountOk = true;
    const readMount = () => {
      mountOk = true;
      for (const f of [mx, my]) {
        const v = f.read();
        const ok = Number.isFinite(v) && Math.abs(v) <= 5;
        f.setError(ok ? null : 'The mount offset must be a number from −5 to 5 m.');
        mountOk &&= ok;
      }
      if (mountOk) mount = { x: mx.read(), y: my.read(), angle: ma.read() * Math.PI / 180 };
    };

    let tree = null, result = null, step = 0;
    const fig = host.figure;

    // a frame's origin and axes drawn in the current frame (tf maps the frame's coordinates to the drawn frame)
    const axes = (scene, tf, name, len, caption = name) => {
      const p = tf([0, 0, len, 0, 0, len]);
      const colour = FRAME_COLOURS[name];
      scene.segments([p[0], p[1], p[2], p[3], p[0], p[1], p[4], p[5]], { colour, width: 2.5 });
      scene.label(p[2], p[3], `${name} x`, { colour });
      // names apart, since frames can coincide (the identity mount puts the sensor on the robot's origin); the map's
      // name sits one line of text under its origin, clear of its x axis at any type size
      const off = { map: [0, 0], robot: [0, 0.15], sensor: [0, -0.45] }[name].map((v) => v * len);
      scene.label(p[0] + off[0], p[1] + off[1], caption, { colour, ...(name === 'map' ? { offset: [6, 18] } : {}) });
    };
    const extentOf = (...sets) => {
      let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      for (const xy of sets) for (let i = 0; i < xy.length; i += 2) {
        if (!Number.isFinite(xy[i])) continue;
        x0 = Math.min(x0, xy[i]); x1 = Math.max(x1, xy[i]); y0 = Math.min(y0, xy[i + 1]); y1 = Math.max(y1, xy[i + 1]);
      }
      const m = 0.05 * Math.max(x1 - x0, y1 - y0);
      return [x0 - m, y0 - m, x1 + m, y1 + m];
    };

    const lesson = {
      recompute() {
        readMount();
        if (!mountOk) return { steps: 0 };
        tree?.dispose();
        tree = buildTree(host.rtl, scan, mount);
        const robotPts = tree.transformPoints('sensor', 'robot', measured);
        const mapStepwise = tree.transformPoints('robot', 'map', robotPts);
        const mapChain = tree.transformPoints('sensor', 'map', measured);
        const chain = tree.tf('sensor', 'map');
        // the neighbours, each through its own pose with the log's mount (the laser at the robot's origin)
        const background = [];
        for (const k of EXCERPT.neighbours) {
          const t = buildTree(host.rtl, scans[k], { x: 0, y: 0, angle: 0 });
          try { background.push(...t.transformPoints('sensor', 'map', scans[k].points)); } finally { t.dispose(); }
        }
        result = {
          sensor: measured, robot: Array.from(robotPts), map: Array.from(mapStepwise), chain: Array.from(mapChain),
          chainMatrix: Array.from(chain.matrix), chainAngle: Math.atan2(chain.rotation[2], chain.rotation[0]),
          chainTranslation: Array.from(chain.translation), background,
        };
        return { steps: STEPS.length };
      },
      show(k) {
        if (k < 0 || !result) { host.text.textContent = 'Correct the mount (marked) to see the frames.'; return; }
        step = Math.max(0, Math.min(STEPS.length - 1, k));
        const name = STEPS[step];
        const inFrame = { sensor: 'sensor', mount: 'robot', pose: 'map', chain: 'map' }[name];
        const pts = { sensor: result.sensor, mount: result.robot, pose: result.map, chain: result.chain }[name];
        const frameTf = (frame) => (xy) => (frame === inFrame ? xy : Array.from(tree.transformPoints(frame, inFrame, xy)));
        const mapView = inFrame === 'map';
        fig.setExtent(...extentOf(pts, mapView ? result.background : [], frameTf('map')([0, 0]), frameTf('robot')([0, 0])));
        const scene = new Scene(`Intel scan ${EXCERPT.scan} in the ${inFrame} frame`);
        if (mapView) scene.points(result.background, { colour: '#c3c8cf', radius: 1.5 });
        // the previous step's points, faint, so the move is visible
        if (name === 'mount') scene.points(result.sensor, { colour: '#f3c4a8', radius: 1.8 });
        if (name === 'pose') scene.points(result.robot, { colour: '#a9c8e6', radius: 1.8 });
        scene.points(pts, { colour: name === 'sensor' ? FRAME_COLOURS.sensor : name === 'mount' ? FRAME_COLOURS.robot : '#222', radius: 2.2 });
        // axes at least 50 CSS px long, so that their names do not pile up on a phone's small figure
        fig.layout();
        const len = Math.max(mapView ? 2 : 0.8, 50 / fig.scale);
        if (mapView) axes(scene, frameTf('map'), 'map', len);
        // with the identity mount the sensor frame is the robot frame: one set of axes, named so
        const same = mount.x === 0 && mount.y === 0 && mount.angle === 0;
        if (inFrame !== 'sensor') axes(scene, frameTf('robot'), 'robot', len, same ? 'robot = sensor' : 'robot');
        if (inFrame === 'sensor' || !same) axes(scene, frameTf('sensor'), 'sensor', 0.6 * len);
        fig.show(scene);

        const m = mount, pose = scan;
        host.text.textContent = {
          sensor: `Step 1 of 4 · sensor frame. Intel scan ${EXCERPT.scan} as the laser measured it: ${measured.length / 2} beams, each point (r cos a, r sin a) in the sensor's own frame, x straight ahead. Nothing is known yet about where the sensor is.`,
          mount: `Step 2 of 4 · sensor → robot. The sensor is mounted at (${f2(m.x)}, ${f2(m.y)}) m on the robot, turned by ${deg(m.angle)}. tree.transformPoints('sensor', 'robot') rotates the points by the mount angle and adds the offset${m.x || m.y || m.angle ? '' : ' (here the identity: the Intel laser sits at the robot\'s origin, so the points do not move)'}.`,
          pose: `Step 3 of 4 · robot → map. The log's corrected pose puts the robot at (${f2(pose.x)}, ${f2(pose.y)}) m, heading ${deg(pose.theta)}. tree.transformPoints('robot', 'map') turns the robot-frame points by θ and shifts them by (x, y). The grey points are the neighbouring scans placed by their own poses: ${m.x || m.y || m.angle ? 'with this mount the walls no longer line up — a miscalibrated sensor looks exactly like this.' : 'the walls line up.'}`,
          chain: `Step 4 of 4 · the chain. The tree stores map → robot → sensor; tree.tf('sensor', 'map') walks up from the sensor and composes the inverses: one rigid transformation, rotation ${deg(result.chainAngle)} and translation (${f2(result.chainTranslation[0])}, ${f2(result.chainTranslation[1])}) m, that takes the measured points straight to the map — the same points as the two steps before.`,
        }[name];
      },
      finalState() {
        return { excerpt: { ...EXCERPT }, step, pose: { x: scan.x, y: scan.y, theta: scan.theta }, mount: { ...mount }, ...result };
      },
      dispose() {
        tree?.dispose();
        tree = null;
        controls.replaceChildren();
      },
    };
    return lesson;
  },
};
