// Serves the built app (dist/) read-only; no directory listing, no path escapes (symlinks included).
import { createReadStream, realpathSync, statSync } from 'node:fs';
import type { IncomingMessage, ServerResponse } from 'node:http';
import { extname, join, normalize, sep } from 'node:path';
import { IO_PATH } from '../protocol/messages';

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.ico': 'image/x-icon',
  '.woff2': 'font/woff2',
  '.wasm': 'application/wasm',
  '.xml': 'application/xml; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
};

/** Source maps (`*.map`, built by vite.config.ts) are served only when this variable is `1`. */
export const SOURCE_MAPS_ENV = 'RUNGSMITH_SERVE_SOURCEMAPS';

/** `Host` values the WebSocket URL may be built from (the gateway has already checked it against its allow-list). */
const HOST_RE = /^(?:[A-Za-z0-9.-]+|\[[0-9A-Fa-f:.]+\])(?::\d{1,5})?$/;

/**
 * The page may load scripts, styles, workers, images and fonts from its own origin only, talk only to its
 * own origin (fetch) and its own /io WebSocket, and may not be framed. Inline styles stay allowed: React
 * and Konva set style attributes. No inline script, and no eval on the page; a Web Worker's script gets
 * its own policy from its response, and there `'unsafe-eval'` is allowed (`forWorker`): the simulator
 * compiles the ladder program to JavaScript (`new Function`) in its worker, which has no DOM.
 */
export function contentSecurityPolicy(host: string | undefined, forWorker = false): string {
  const ws = host !== undefined && HOST_RE.test(host) ? ` ws://${host.toLowerCase()}${IO_PATH}` : '';
  return [
    "default-src 'self'",
    forWorker ? "script-src 'self' 'unsafe-eval'" : "script-src 'self'",
    "style-src 'self' 'unsafe-inline'",
    "img-src 'self' data: blob:",
    "font-src 'self'",
    `connect-src 'self'${ws}`,
    "worker-src 'self'",
    "object-src 'none'",
    "base-uri 'none'",
    "form-action 'none'",
    "frame-ancestors 'none'",
  ].join('; ');
}

/** The real path of `file` if it is a regular file inside `realRoot` (after following every symlink), else undefined. */
function realFileInside(file: string, realRoot: string): { path: string; size: number } | undefined {
  try {
    const real = realpathSync(file);
    if (!real.startsWith(realRoot.endsWith(sep) ? realRoot : realRoot + sep)) return undefined;
    const st = statSync(real);
    return st.isFile() ? { path: real, size: st.size } : undefined;
  } catch {
    return undefined;
  }
}

/** The security headers every HTTP response of the gateway carries (refusals included). */
export function setSecurityHeaders(req: IncomingMessage, res: ServerResponse): void {
  // Browsers mark a worker's script request with `Sec-Fetch-Dest: worker`; only that response allows eval.
  const forWorker = req.headers['sec-fetch-dest'] === 'worker';
  res.setHeader('Content-Security-Policy', contentSecurityPolicy(req.headers.host, forWorker));
  res.setHeader('Vary', 'Sec-Fetch-Dest');
  res.setHeader('X-Content-Type-Options', 'nosniff');
  res.setHeader('X-Frame-Options', 'DENY');
  res.setHeader('Referrer-Policy', 'no-referrer');
}

export function serveStatic(root: string | null, req: IncomingMessage, res: ServerResponse): void {
  setSecurityHeaders(req, res);
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    res.writeHead(405, { Allow: 'GET, HEAD', 'Content-Type': 'text/plain' }).end('method not allowed\n');
    return;
  }
  if (!root) {
    res.writeHead(404, { 'Content-Type': 'text/plain' }).end('this gateway serves no app; the WebSocket endpoint is /io\n');
    return;
  }
  let path: string;
  try {
    path = decodeURIComponent(new URL(req.url ?? '/', 'http://localhost').pathname);
  } catch {
    res.writeHead(400, { 'Content-Type': 'text/plain' }).end('bad path\n');
    return;
  }
  const file = normalize(join(root, path === '/' ? 'index.html' : path));
  if (file !== root && !file.startsWith(root.endsWith(sep) ? root : root + sep)) {
    res.writeHead(403, { 'Content-Type': 'text/plain' }).end('forbidden\n');
    return;
  }
  if (extname(file) === '.map' && process.env[SOURCE_MAPS_ENV] !== '1') {
    res.writeHead(404, { 'Content-Type': 'text/plain' }).end('not found\n');
    return;
  }
  let realRoot: string;
  try {
    realRoot = realpathSync(root);
  } catch {
    res.writeHead(404, { 'Content-Type': 'text/plain' }).end('not found\n');
    return;
  }
  // Symlinks are followed only as far as they stay inside the app directory; the real path is what is read.
  const found = realFileInside(file, realRoot) ?? (extname(path) ? undefined : realFileInside(join(root, 'index.html'), realRoot)); // client-side routes
  if (!found) {
    res.writeHead(404, { 'Content-Type': 'text/plain' }).end('not found\n');
    return;
  }
  const isIndex = found.path === join(realRoot, 'index.html');
  res.writeHead(200, {
    'Content-Type': TYPES[extname(found.path)] ?? 'application/octet-stream',
    'Content-Length': found.size,
    'Cache-Control': isIndex ? 'no-cache' : 'public, max-age=3600',
  });
  if (req.method === 'HEAD') {
    res.end();
    return;
  }
  createReadStream(found.path).on('error', () => res.destroy()).pipe(res);
}
