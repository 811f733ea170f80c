// The rtl command's options: its own small argv parser (so that every bad option, e.g. `--scan -1`, an unknown
// option or a missing value, gets a message of this package rather than Node's), then checks of each value and of
// the combinations. parseCommandLine throws UsageError (exit code 2); the message is printed after "rtl: ".
import { extname } from 'node:path';
import { defaults } from 'rtl-wasm';

export class UsageError extends Error {}

// name -> { short, value: true when the option takes a value }
const SPEC = {
  type: { short: 't', value: true },
  scan: { value: true },
  'max-range': { value: true },
  beams: { value: true },
  layout: { value: true },
  ring: { value: true },
  column: { value: true },
  fit: {},
  segment: { short: 's' },
  'no-segment': {},
  raw: {},
  segmenter: { value: true },
  step: { value: true },
  lower: { value: true },
  upper: { value: true },
  scaling: { value: true },
  vectorize: { short: 'm', value: true },
  sigma: { value: true },
  delta: { value: true },
  strict: {},
  epsilon: { value: true },
  'simplex-shift': { value: true },
  'max-iterations': { value: true },
  primitive: { value: true },
  'min-points': { value: true },
  'max-vertices': { value: true },
  format: { short: 'f', value: true },
  standalone: {},
  dim: { value: true },
  camera: { value: true },
  output: { short: 'o', value: true },
  topic: { value: true },
  start: { value: true },
  end: { value: true },
  jobs: { short: 'j', value: true },
  progress: {},
  'no-progress': {},
  help: { short: 'h' },
  version: {},
};
const SHORT = Object.fromEntries(Object.entries(SPEC).filter(([, s]) => s.short).map(([n, s]) => [s.short, n]));

export const METHODS = ['ftls', 'aftls', 'itls', 'dp', 'rw'];
const FORMATS = ['json', 'svg', 'tikz'];
const TYPES = ['carmen', 'bin', 'csv', 'mcap', 'bag'];
const LOG_TYPES = ['mcap', 'bag'];

export function typeOfFile(file) {
  const ext = extname(file).toLowerCase();
  if (ext === '.log' || ext === '.carmen' || ext === '.clf') return 'carmen';
  if (ext === '.bin') return 'bin';
  if (ext === '.csv' || ext === '.txt' || ext === '.xyz') return 'csv';
  if (ext === '.mcap') return 'mcap';
  if (ext === '.bag') return 'bag';
  return undefined;
}

function editDistance(a, b) {
  let prev = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const row = [i];
    for (let j = 1; j <= b.length; j++) row[j] = Math.min(prev[j] + 1, row[j - 1] + 1, prev[j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
    prev = row;
  }
  return prev[b.length];
}

function unknownOption(name) {
  const close = Object.keys(SPEC).filter((n) => n.startsWith(name) || editDistance(n, name) <= 2);
  return new UsageError(`unknown option --${name}${close.length ? ` (did you mean ${close.map((n) => `--${n}`).join(' or ')}?)` : ''}`);
}

// A value may start with '-' when it is a number (`--scan -1` is then rejected by the range check, with its value),
// never when it looks like another option (`--scan --fit` means the value is missing).
const looksLikeOption = (arg) => arg.startsWith('-') && arg !== '-' && !/^-\.?\d/.test(arg);

// argv -> { values: {name: string | true}, positionals }
export function splitArgv(argv) {
  const values = {}, positionals = [];
  const set = (name, value, shown) => {
    if (name in values) throw new UsageError(`${shown} is given more than once`);
    values[name] = value;
  };
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    if (arg === '--') { positionals.push(...argv.slice(i + 1)); break; }
    if (arg === '-' || !arg.startsWith('-')) { positionals.push(arg); continue; }
    const takeValue = (name, shown, inline) => {
      if (inline !== undefined) return inline;
      if (i + 1 >= argv.length || looksLikeOption(argv[i + 1])) throw new UsageError(`${shown} needs a value`);
      return argv[++i];
    };
    if (arg.startsWith('--')) {
      const eq = arg.indexOf('=');
      const name = eq < 0 ? arg.slice(2) : arg.slice(2, eq);
      const inline = eq < 0 ? undefined : arg.slice(eq + 1);
      const spec = SPEC[name];
      if (!spec) throw unknownOption(name);
      if (!spec.value && inline !== undefined) throw new UsageError(`--${name} takes no value, got "--${name}=${inline}"`);
      set(name, spec.value ? takeValue(name, `--${name}`, inline) : true, `--${name}`);
      continue;
    }
    // Short options: booleans may be grouped (-sh); a value follows its letter (-mftls) or is the next argument.
    for (let k = 1; k < arg.length; k++) {
      const name = SHORT[arg[k]];
      if (!name) throw new UsageError(`unknown option -${arg[k]}${arg.length > 2 ? ` (in "${arg}")` : ''}`);
      if (!SPEC[name].value) { set(name, true, `-${arg[k]}`); continue; }
      set(name, takeValue(name, `-${arg[k]} (--${name})`, k + 1 < arg.length ? arg.slice(k + 1) : undefined), `-${arg[k]}`);
      break;
    }
  }
  return { values, positionals };
}

// --camera FOV[,DX,DY,DZ]: the package's toTikz camera {fov, direction} (degrees in (0, 179], any non-zero vector).
function camera(text) {
  if (text === undefined) return undefined;
  const parts = text.split(',').map((t) => t.trim());
  const x = parts.map(Number);
  if ((parts.length !== 1 && parts.length !== 4) || parts.some((t) => t === '') || !x.every(Number.isFinite)) {
    throw new UsageError(`--camera must be FOV or FOV,DX,DY,DZ (numbers), got "${text}"`);
  }
  if (!(x[0] > 0 && x[0] <= 179)) throw new UsageError(`--camera field of view must be in (0, 179] degrees, got ${x[0]}`);
  if (parts.length === 4 && !(Math.hypot(x[1], x[2], x[3]) > 0)) throw new UsageError(`--camera direction must not be zero, got "${text}"`);
  return parts.length === 4 ? { fov: x[0], direction: x.slice(1) } : { fov: x[0] };
}

export function parseCommandLine(argv) {
  const { values: v, positionals } = splitArgv(argv);
  if (v.help || v.version) return { help: v.help, version: v.version };
  if (positionals.length === 0) throw new UsageError('missing input file');
  // Several inputs: robot logs only (each one processed whole, --jobs at a time).
  if (positionals.length > 1) {
    const forced = v.type?.toLowerCase();
    const notLog = positionals.find((f) => !LOG_TYPES.includes(forced ?? typeOfFile(f)));
    if (notLog !== undefined) throw new UsageError(`expected one input file, got ${positionals.length}: ${positionals.join(' ')} (several inputs must all be .mcap or .bag logs; "${notLog}" is not)`);
  }

  const num = (name, def, { min = -Infinity, integer = false, positive = false } = {}) => {
    if (v[name] === undefined) return def;
    const text = v[name].trim();
    const x = Number(text);
    if (text === '' || !Number.isFinite(x)) throw new UsageError(`--${name} must be a number, got "${v[name]}"`);
    if (integer && !Number.isInteger(x)) throw new UsageError(`--${name} must be an integer, got "${v[name]}"`);
    if (positive && !(x > 0)) throw new UsageError(`--${name} must be > 0, got "${v[name]}"`);
    if (x < min) throw new UsageError(`--${name} must be >= ${min}, got "${v[name]}"`);
    return x;
  };
  const oneOf = (name, list, def) => {
    if (v[name] === undefined) return def;
    const x = v[name].toLowerCase();
    if (!list.includes(x)) throw new UsageError(`--${name} must be one of ${list.join(', ')}, got "${v[name]}"`);
    return x;
  };

  const file = positionals[0];
  let type = oneOf('type', TYPES, undefined);
  if (!type) {
    type = typeOfFile(file);
    if (!type) throw new UsageError(`cannot tell the input type of "${file}" from its extension; pass --type carmen|bin|csv|mcap|bag`);
  }
  const isLog = LOG_TYPES.includes(type);
  const noSegment = Boolean(v['no-segment'] || v.raw);
  if (noSegment && v.segment) throw new UsageError(`--segment and ${v.raw ? '--raw' : '--no-segment'} contradict each other`);
  const segmenter = oneOf('segmenter', ['car', 'ia'], 'car');
  // The package's defaults (its `defaults` export): the same values as a call without the option.
  const seg = segmenter === 'car' ? defaults.segment : defaults.streamSegmenter, vect = defaults.vectorize;
  const opts = {
    file,
    files: positionals,
    type,
    isLog,
    topic: v.topic,
    start: num('start', undefined, { min: 0 }),
    end: num('end', undefined, { min: 0 }),
    jobs: num('jobs', undefined, { min: 1, integer: true }),
    progress: v['no-progress'] ? false : v.progress ? true : undefined,
    scan: num('scan', 0, { min: 0, integer: true }),
    maxRange: num('max-range', undefined, { positive: true }),
    beams: num('beams', undefined, { integer: true, positive: true }),
    layout: oneOf('layout', ['column', 'row'], 'column'),
    ring: num('ring', undefined, { min: 0, integer: true }),
    column: num('column', undefined, { min: 0, integer: true }),
    fit: Boolean(v.fit),
    segment: !noSegment,
    segmenter,
    scaling: num('scaling', defaults.streamSegmenter.scaling, { min: 0 }),
    // CAR step s compares up to s-1 previous points, so 2 links consecutive points; IA's window of 3.
    step: num('step', seg.step, { min: 1, integer: true }),
    lower: num('lower', seg.lowerBound, { min: 0 }),
    upper: num('upper', seg.upperBound, { min: 0 }),
    method: oneOf('vectorize', METHODS, undefined),
    sigma: num('sigma', vect.sigma, { positive: true }),
    delta: num('delta', vect.delta, { positive: true }),
    strict: Boolean(v.strict),
    epsilon: num('epsilon', vect.epsilon, { positive: true }),
    simplexShift: num('simplex-shift', vect.simplexShift, { min: 1, integer: true }),
    maxIterations: num('max-iterations', vect.maxIterations, { min: 1, integer: true }),
    primitive: oneOf('primitive', ['line', 'plane'], 'line'),
    minPoints: num('min-points', 3, { min: 2, integer: true }),
    maxVertices: num('max-vertices', undefined, { min: 2, integer: true }),
    format: oneOf('format', FORMATS, 'json'),
    standalone: Boolean(v.standalone),
    dim: num('dim', 2, { integer: true }),
    camera: camera(v.camera),
    output: v.output,
  };
  if (opts.maxVertices !== undefined) {
    // The whole scan within a vertex budget (extractPolylines) instead of segment + fit/vectorize.
    for (const k of ['vectorize', 'fit', 'segment', 'no-segment', 'raw', 'segmenter', 'step', 'lower', 'upper', 'scaling', 'min-points', 'sigma', 'delta', 'strict', 'epsilon', 'simplex-shift', 'max-iterations', 'primitive'])
      if (v[k] !== undefined) throw new UsageError(`--${k} does not apply with --max-vertices (the whole scan is extracted within the vertex budget)`);
    if (type !== 'carmen' && type !== 'csv' && !isLog) throw new UsageError('--max-vertices needs a 2D scan in beam order (a CARMEN log, a CSV of x,y or a LaserScan log)');
    opts.segment = false;
  }
  if (opts.lower > opts.upper) throw new UsageError(`--lower (${opts.lower}) must not exceed --upper (${opts.upper})`);
  if (noSegment) {
    if (!opts.method && !opts.fit) throw new UsageError(`${v.raw ? '--raw' : '--no-segment'} needs --fit or --vectorize (there is nothing else to do)`);
    for (const k of ['segmenter', 'step', 'lower', 'upper', 'scaling']) {
      if (v[k] !== undefined) throw new UsageError(`--${k} applies to segmentation, not with ${v.raw ? '--raw' : '--no-segment'}`);
    }
  }
  if (isLog) {
    for (const k of ['beams', 'layout']) if (v[k] !== undefined) throw new UsageError(`--${k} applies to binary scans only (a log's PointCloud2 says its own)`);
    if (opts.ring !== undefined && opts.column !== undefined) throw new UsageError('pass either --ring or --column, not both');
    if (opts.start !== undefined && opts.end !== undefined && opts.end < opts.start) throw new UsageError(`--end (${opts.end}) must not be before --start (${opts.start})`);
    if (v.progress && v['no-progress']) throw new UsageError('--progress and --no-progress contradict each other');
    if (opts.format !== 'json') {
      if (!opts.output || !opts.output.includes('%d')) throw new UsageError(`--format ${opts.format} on a log writes one file per scan: pass --output with %d (the scan index), e.g. -o scan-%d.${opts.format === 'svg' ? 'svg' : 'tex'}`);
      if (positionals.length > 1 && !opts.output.includes('%f')) throw new UsageError('several logs with --format svg/tikz: --output needs %f (the log name) as well as %d');
    }
    if (positionals.length > 1 && opts.format === 'json' && opts.output?.includes('%f')) throw new UsageError('JSON Lines of several logs go to one file (each line names its log): --output must not contain %f');
  } else {
    for (const k of ['topic', 'start', 'end', 'jobs', 'progress', 'no-progress']) if (v[k] !== undefined) throw new UsageError(`--${k} applies to robot logs (.mcap, .bag) only`);
  }
  if (opts.type !== 'bin') {
    if (!isLog) for (const k of ['beams', 'ring', 'column', 'layout']) if (v[k] !== undefined) throw new UsageError(`--${k} applies to binary scans only`);
  } else {
    if (opts.beams === undefined) throw new UsageError('a binary scan needs --beams N (the number of rings)');
    if (opts.ring !== undefined && opts.column !== undefined) throw new UsageError('pass either --ring or --column, not both');
  }
  if (opts.type !== 'carmen') {
    for (const k of ['scan', 'max-range']) if (v[k] !== undefined) throw new UsageError(`--${k} applies to CARMEN logs only`);
  }
  if (v.scaling !== undefined && opts.segmenter !== 'ia') throw new UsageError('--scaling applies to --segmenter ia only');
  if (opts.strict && !['ftls', 'aftls'].includes(opts.method)) throw new UsageError('--strict applies to --vectorize ftls or aftls only');
  if (opts.primitive === 'plane' && opts.method !== 'aftls') throw new UsageError('--primitive plane needs --vectorize aftls');
  if (opts.standalone && opts.format !== 'tikz') throw new UsageError('--standalone applies to --format tikz only');
  if (opts.dim !== 2 && opts.dim !== 3) throw new UsageError(`--dim must be 2 or 3, got "${v.dim}"`);
  if (opts.dim === 3 && opts.format !== 'tikz') throw new UsageError('--dim 3 draws TikZ only: pass --format tikz');
  if (opts.camera && opts.dim !== 3) throw new UsageError('--camera applies to --dim 3 only');
  return opts;
}
