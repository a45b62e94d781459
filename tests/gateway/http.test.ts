// The app is served by the gateway itself: same origin for the page and /io, nothing else exposed.
import { mkdirSync, mkdtempSync, symlinkSync, writeFileSync } from 'node:fs';
import { request } from 'node:http';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { SOURCE_MAPS_ENV } from '../../src/gateway/staticFiles';

function get(port: number, path: string, method = 'GET'): Promise<{ status: number; type: string; body: string }> {
  return new Promise((resolve, reject) => {
    const req = request({ host: '127.0.0.1', port, path, method }, (res) => {
      let body = '';
      res.setEncoding('utf8');
      res.on('data', (d: string) => (body += d));
      res.on('end', () => resolve({ status: res.statusCode ?? 0, type: String(res.headers['content-type'] ?? ''), body }));
    });
    req.on('error', reject);
    req.end();
  });
}

function headersOf(port: number, path: string, headers: Record<string, string> = {}): Promise<Record<string, string | string[] | undefined>> {
  return new Promise((resolve, reject) => {
    const req = request({ host: '127.0.0.1', port, path, headers }, (res) => {
      res.resume();
      resolve(res.headers);
    });
    req.on('error', reject);
    req.end();
  });
}

describe('gateway HTTP', () => {
  let gw: RunningGateway;
  beforeAll(async () => {
    const root = mkdtempSync(join(tmpdir(), 'rungsmith-dist-'));
    mkdirSync(join(root, 'dist/assets'), { recursive: true });
    writeFileSync(join(root, 'dist/index.html'), '<!doctype html><title>Rungsmith</title>');
    writeFileSync(join(root, 'dist/assets/app.js'), 'console.log(1)');
    writeFileSync(join(root, 'dist/assets/app.js.map'), '{"version":3,"sources":["secret-source.ts"]}');
    writeFileSync(join(root, 'secret.txt'), 'do not serve');
    mkdirSync(join(root, 'private'));
    writeFileSync(join(root, 'private/key.txt'), 'do not serve');
    // Links inside the app directory that lead out of it, and one that stays inside.
    symlinkSync(join(root, 'secret.txt'), join(root, 'dist/assets/leak.txt'));
    symlinkSync(join(root, 'secret.txt'), join(root, 'dist/leak'));
    symlinkSync(join(root, 'private'), join(root, 'dist/private'));
    symlinkSync(join(root, 'dist/assets/app.js'), join(root, 'dist/assets/alias.js'));
    gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: null } }), distDir: join(root, 'dist') });
  });
  afterAll(() => gw?.close());

  it('serves the built app with its content types', async () => {
    expect(await get(gw.port, '/')).toMatchObject({ status: 200, type: 'text/html; charset=utf-8', body: expect.stringContaining('Rungsmith') });
    expect(await get(gw.port, '/assets/app.js')).toMatchObject({ status: 200, type: 'text/javascript; charset=utf-8' });
    expect((await get(gw.port, '/assets/missing.js')).status).toBe(404);
  });

  it('never serves files outside the app directory and accepts only GET and HEAD', async () => {
    for (const path of ['/../secret.txt', '/..%2fsecret.txt', '/%2e%2e/secret.txt', '/assets/..%2f..%2fsecret.txt']) {
      const r = await get(gw.port, path);
      expect(r.body, path).not.toContain('do not serve');
    }
    expect((await get(gw.port, '/', 'POST')).status).toBe(405);
    expect((await get(gw.port, '/', 'HEAD')).status).toBe(200);
  });

  it('refuses symlinks that lead out of the app directory, and follows those that stay inside', async () => {
    for (const path of ['/assets/leak.txt', '/private/key.txt']) {
      const r = await get(gw.port, path);
      expect(r.status, path).toBe(404);
      expect(r.body, path).not.toContain('do not serve');
    }
    // Without an extension a miss is a client-side route: the app's index page, never the linked file.
    const route = await get(gw.port, '/leak');
    expect(route.body).not.toContain('do not serve');
    expect(route.body).toContain('Rungsmith');
    expect(await get(gw.port, '/assets/alias.js')).toMatchObject({ status: 200, body: 'console.log(1)' });
  });

  it('sends a Content-Security-Policy that forbids framing and allows only its own origin and /io WebSocket', async () => {
    for (const path of ['/', '/assets/app.js', '/assets/missing.js']) {
      const h = await headersOf(gw.port, path);
      const csp = String(h['content-security-policy']);
      expect(csp, path).toContain("frame-ancestors 'none'");
      expect(csp, path).toContain("script-src 'self'");
      expect(csp, path).toContain(`connect-src 'self' ws://127.0.0.1:${gw.port}/io`);
      expect(csp, path).not.toContain('unsafe-eval');
      expect(h['x-content-type-options'], path).toBe('nosniff');
    }
    // Only a Web Worker's script may eval (the simulator compiles the program in its worker).
    const worker = String((await headersOf(gw.port, '/assets/app.js', { 'Sec-Fetch-Dest': 'worker' }))['content-security-policy']);
    expect(worker).toContain("script-src 'self' 'unsafe-eval'");
    expect(worker).toContain("frame-ancestors 'none'");
    // The refusal of a foreign Host name carries the same headers.
    const refused = await headersOf(gw.port, '/', { Host: `rebind.example:${gw.port}` });
    expect(String(refused['content-security-policy'])).toContain("frame-ancestors 'none'");
    expect(refused['x-content-type-options']).toBe('nosniff');
  });

  it('does not serve source maps unless RUNGSMITH_SERVE_SOURCEMAPS=1', async () => {
    const r = await get(gw.port, '/assets/app.js.map');
    expect(r.status).toBe(404);
    expect(r.body).not.toContain('secret-source');
    process.env[SOURCE_MAPS_ENV] = '1';
    try {
      expect(await get(gw.port, '/assets/app.js.map')).toMatchObject({ status: 200, body: expect.stringContaining('secret-source') });
    } finally {
      delete process.env[SOURCE_MAPS_ENV];
    }
  });
});
