#!/usr/bin/env node
// rtl: the rtl-wasm package's command-line tool. Reads a scan (CARMEN log, organised LiDAR binary or CSV), segments
// it into clusters, fits total-least-squares lines and/or vectorizes each cluster with the package's WebAssembly
// build, and writes JSON, SVG or TikZ. Exit codes: 0 ok, 1 bad input data, 2 bad usage, 3 a function this build of
// the package does not have.
import { readFileSync, writeFileSync } from 'node:fs';
import init, { defaults } from 'rtl-wasm';
import { parseCommandLine, UsageError } from './options.js';
import { InputError, MissingFeature, asUsageError, loadPoints, render, run } from './pipeline.js';

const { segment: seg, streamSegmenter: stream, vectorize: vect } = defaults;
const HELP = `Usage: rtl [options] <file>      (use - to read standard input)
       rtl [options] <log.mcap|log.bag>...   (robot logs: every scan of a topic)

Cuts ordered 2D/3D points into clusters with the batch segmenter, then fits
total-least-squares lines to the clusters and/or turns each cluster into line
segments (or planes), and writes JSON, SVG or TikZ (rtl-wasm package).

Input
  -t, --type TYPE        carmen | bin | csv; default from the extension
                         (.log .carmen .clf -> carmen, .bin -> bin, .csv .txt .xyz -> csv)
      --scan N           scan of a CARMEN log, 0-based (default 0)
      --max-range M      CARMEN: ranges >= M metres are "no return" (gaps); default: the
                         log's own no-return value (from its parameters, or the maximum
                         range that recurs in it)
      --beams N          beams (rings) of an organised binary scan (required for bin)
      --layout L         column | row: point order of the binary scan (default column)
      --ring K           take ring K of the binary scan (default 0)
      --column C         take column C of the binary scan instead of a ring
  CSV: one point per line, x,y or x,y,z (comma, semicolon or blanks); '#' comments;
       an optional header line; empty, NaN or non-finite coordinates mark gaps.

Robot logs (.mcap: ROS 2 / MCAP, chunks none, lz4 or zstd; .bag: ROS 1), read with the
optional packages @mcap/core, @mcap/support, @foxglove/rosmsg, @foxglove/rosmsg2-serialization,
@foxglove/rosmsg-serialization, @foxglove/rosbag. Every scan of the topic runs through the
pipeline below; JSON output is JSON Lines (one scan a line, in log order); --format svg|tikz
writes one file per scan (--output with %d = scan index, %f = log name). Ctrl-C or a corrupt
message stops after complete output for the scans done and says where (exit 130 / 1).
      --topic T          sensor_msgs/LaserScan or PointCloud2 topic (default: the log's
                         only LaserScan topic); clouds take --ring K (default 0) or --column C
      --start S, --end S log time window in seconds (inclusive)
  -j, --jobs N           logs processed at once, in worker threads (default: the cores)
      --progress         progress bar on stderr (default: when stderr is a terminal)
      --no-progress      never draw it

Segmentation (always first, unless --no-segment)
  -s, --segment          segment (the default; accepted for clarity)
      --no-segment       do not segment: fit/vectorize the raw chain, i.e. all returns
      --raw              (non-gap points) in scan order, as one cluster
      --segmenter S      car (batch, the scan as a closed loop; default) | ia (streaming)
      --step N           car: each point is compared with up to N-1 previous points
                         (default ${seg.step}: consecutive points are linked; 1 links nothing);
                         ia: the window of the last N points (default ${stream.step})
      --lower M          lower bound of the distance threshold in metres (default ${seg.lowerBound})
      --upper M          upper bound in metres (default ${seg.upperBound})
      --scaling K        ia: threshold = K * range, clamped to the bounds (default ${stream.scaling})

Line fit
      --fit              total-least-squares line through each cluster of at least
                         --min-points points

Vectorization
  -m, --vectorize METHOD ftls | aftls | itls | dp | rw, applied to each cluster
      --sigma M          max RMS distance of points from a line (TLS methods, default ${vect.sigma})
      --delta M          corner tolerance of FTLS/AFTLS (default ${vect.delta})
      --strict           FTLS/AFTLS: RTL's strict behaviour: a cluster whose corners cannot
                         all be met within --delta gets no segments ("failed" in the JSON).
                         Default (split mode): the polyline breaks at such a corner, so the
                         cluster becomes several polylines ("breaks" in the JSON).
      --epsilon M        tolerance of Douglas-Peucker / Reumann-Witkam (default ${vect.epsilon})
      --simplex-shift N  AFTLS optimizer start simplex shift (default ${vect.simplexShift})
      --max-iterations N AFTLS optimizer iteration cap (default ${vect.maxIterations})
      --primitive P      line | plane, for 3D points (default line; plane needs aftls)
      --min-points N     clusters with fewer points are not fitted/vectorized (default 3)
      --max-vertices J   instead of segmenting and vectorizing: polylines over the whole 2D
                         scan with at most J vertices, minimising the radial error of the
                         beams (extractPolylines); JSON "budget": polylines, segments with
                         their (r, theta) line and covariance, rmse, explained, score

Output
  -f, --format FMT       json | svg | tikz (default json); SVG/TikZ titles name the scan,
                         the segmenter, the method and their parameters
      --standalone       TikZ: a complete LaTeX document instead of a tikzpicture
      --dim D            2 (default) | 3: with --format tikz, 3 draws 3D points (bin, or
                         CSV x,y,z) through the library's 3D renderer: clusters in colours,
                         the segments, and the planes of --primitive plane
      --camera F[,X,Y,Z] --dim 3: field of view F in degrees (default 60) and the viewing
                         direction (default 0,0,-1: looking down); the scene is fitted
  -o, --output FILE      write to FILE instead of standard output
  -h, --help             show this help
      --version          show the package version

JSON indices are the package API's: each segment (or plane) has "cluster" (its number in
segmentation.clusters, null with --no-segment) and "indices": [begin, end), half-open
indices into its cluster's chain, the list of point indices segmentation.clusters[cluster]
(with --no-segment: "chain"), exactly as vectorize() returns them for that chain. So chain
positions begin..end-1 are the points the segment was fitted to (dp/rw: the span between two
kept points). FTLS/AFTLS "breaks" and "failed" give "boundary" as a chain index too, with
the crossing distance (null: the two lines do not cross) and delta. Fits give the cluster, "first" and "last" (point indices of
the cluster's first and last point) and the line.

Exit status: 0 on success, 1 when the input cannot be read or parsed, 2 on bad options,
3 when this build of rtl-wasm lacks a function the options need.

Examples
  rtl tests/data/intel.log --scan 3 -m ftls --sigma 0.02 -f svg -o scan3.svg
  rtl tests/data/rellis3d-os1-4x2048.bin --beams 4 --ring 1 --upper 0.8
  rtl points.csv --no-segment -m dp --epsilon 0.05
  rtl robot.mcap --topic /scan -m ftls -o scans.jsonl
  rtl logs/*.bag --topic /base_scan --jobs 2 -m dp -f svg -o out/%f-%d.svg
  rtl points.csv --no-segment --fit
  rtl tests/data/rellis3d-os1-4x2048.bin --beams 4 --ring 1 -m itls -f tikz --dim 3 --camera 50,1,-1,-1
`;

const HINT = "Try 'rtl --help' for more information.\n";

async function main(argv) {
  let opts;
  try {
    opts = parseCommandLine(argv);
  } catch (e) {
    if (e instanceof UsageError) {
      process.stderr.write(`rtl: ${e.message}\n${HINT}`);
      return 2;
    }
    throw e;
  }
  if (opts.help) { process.stdout.write(HELP); return 0; }
  if (opts.version) {
    const pkg = JSON.parse(readFileSync(new URL('../package.json', import.meta.url), 'utf8'));
    process.stdout.write(`${pkg.version}\n`);
    return 0;
  }
  try {
    const rtl = await init();
    if (opts.isLog) return await (await import('./log-run.js')).runLogs(rtl, opts);
    const input = await loadPoints(rtl, opts);
    const result = run(rtl, opts, input);
    const text = render(rtl, opts, input, result);
    if (opts.output) {
      try {
        writeFileSync(opts.output, text);
      } catch (e) {
        throw new InputError(`cannot write "${opts.output}": ${e.message}`);
      }
    } else {
      process.stdout.write(text);
    }
    return 0;
  } catch (caught) {
    const e = asUsageError(caught);
    if (e instanceof UsageError) {
      process.stderr.write(`rtl: ${e.message}\n${HINT}`);
      return 2;
    }
    process.stderr.write(`rtl: ${e.message}\n`);
    if (e instanceof MissingFeature) return 3;
    // Data errors: our own, or a TypeError/RangeError from the package naming what was wrong.
    return 1;
  }
}

process.exitCode = await main(process.argv.slice(2));
