#!/usr/bin/env node
// Static server for the demo page: serves the repository root on 127.0.0.1 so that the page can load /dist/ (the
// built package), /tests/data/ (real scans) and /web/. Bound to loopback only: it is a dev tool.
// One path is built, not read: /vendor/rtl-wasm-logs.js, the package's `rtl-wasm/logs` entry bundled at serve time
// with its optional peers (@mcap/*, @foxglove/*) from node_modules (web/vendor-logs.js), so that a Web Worker,
// which sees no import map, can read MCAP files and ROS bags without a CDN. Everything else needs no dependency.
//   node web/serve.js            -> http://127.0.0.1:8080/web/   (PORT=0 picks a free port)
//   RTL_SERVE_ROOT=dir node web/serve.js   serves dir instead of the repository
// The first stdout line is the page URL, so scripts and tests can read the port back.
import { createServer } from 'node:http';
import { createReadStream, promises as fs } from 'node:fs';
import { extname, join, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { LOGS_BUNDLE_PATH, bundleLogs } from './vendor-logs.js';

// RTL_SERVE_ROOT serves another folder (e.g. a built app); by default the repository this file lives in.
const ROOT = resolve(process.env.RTL_SERVE_ROOT || fileURLToPath(new URL('..', import.meta.url)));
const HOST = '127.0.0.1';

// Correct types matter: Chromium only streams-compiles wasm served as application/wasm, and refuses ES modules
// served with a non-JavaScript type.
const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.htm': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.cjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/plain; charset=utf-8',
  '.log': 'text/plain; charset=utf-8',
  '.csv': 'text/csv; charset=utf-8',
  '.tex': 'text/plain; charset=utf-8',
  '.ts': 'text/plain; charset=utf-8',
  '.bin': 'application/octet-stream',
};

function send(res, status, text) {
  res.writeHead(status, { 'Content-Type': 'text/plain; charset=utf-8', 'Cache-Control': 'no-store' });
  res.end(text + '\n');
}

// Maps a URL path to a file inside ROOT, or null when the path escapes ROOT (after decoding, so %2e%2e is caught).
export function resolveInside(root, urlPath) {
  let decoded;
  try {
    decoded = decodeURIComponent(urlPath);
  } catch {
    return null;
  }
  if (decoded.includes('\0')) return null;
  const full = resolve(join(root, decoded));
  if (full !== root && !full.startsWith(root + sep)) return null;
  return full;
}

export function createStaticServer(root = ROOT) {
  return createServer(async (req, res) => {
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      res.setHeader('Allow', 'GET, HEAD');
      return send(res, 405, 'method not allowed');
    }
    let pathname;
    try {
      pathname = new URL(req.url, `http://${HOST}`).pathname;
    } catch {
      return send(res, 400, 'bad request');
    }
    if (pathname === LOGS_BUNDLE_PATH) {
      try {
        const code = await bundleLogs(root);
        res.writeHead(200, { 'Content-Type': MIME['.js'], 'Content-Length': Buffer.byteLength(code), 'Cache-Control': 'no-cache' });
        return res.end(req.method === 'HEAD' ? undefined : code);
      } catch (e) {
        return send(res, 503, `${LOGS_BUNDLE_PATH}: ${e.message}`);
      }
    }
    // The generated API references (docs/build-references.mjs writes build/docs/) are served beside the page.
    const reference = /^\/docs\/(js|cpp)(\/.*)?$/.exec(pathname);
    let file = reference ? resolveInside(join(root, 'build', 'docs', reference[1]), reference[2] ?? '/') : resolveInside(root, pathname);
    if (!file) return send(res, 403, 'forbidden');
    try {
      let st = await fs.stat(file);
      if (st.isDirectory()) {
        if (!pathname.endsWith('/')) {
          res.writeHead(301, { Location: pathname + '/' });
          return res.end();
        }
        file = join(file, 'index.html');
        st = await fs.stat(file);
      }
      if (!st.isFile()) return send(res, 404, 'not found');
      res.writeHead(200, {
        'Content-Type': MIME[extname(file).toLowerCase()] || 'application/octet-stream',
        'Content-Length': st.size,
        'Cache-Control': 'no-cache',
        'X-Content-Type-Options': 'nosniff',
      });
      if (req.method === 'HEAD') return res.end();
      createReadStream(file).on('error', () => res.destroy()).pipe(res);
    } catch {
      send(res, 404, 'not found');
    }
  });
}

const isMain = process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url);
if (isMain) {
  const port = process.env.PORT === undefined || process.env.PORT === '' ? 8080 : Number(process.env.PORT);
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`serve.js: PORT must be an integer in 0..65535, got "${process.env.PORT}"`);
    process.exit(2);
  }
  const server = createStaticServer();
  server.on('error', (e) => {
    console.error(`serve.js: cannot listen on ${HOST}:${port}: ${e.message}`);
    process.exit(1);
  });
  server.listen(port, HOST, () => {
    console.log(`http://${HOST}:${server.address().port}${process.env.RTL_SERVE_ROOT ? "/" : "/web/"}`);
    console.log(`serving ${ROOT} (pid ${process.pid}; stop with kill ${process.pid})`);
  });
  for (const sig of ['SIGINT', 'SIGTERM']) process.on(sig, () => {
    server.close(() => process.exit(0));
    server.closeAllConnections(); // keep-alive sockets from a browser would otherwise hold close() open
  });
}
