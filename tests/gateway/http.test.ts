// The app is served by the gateway itself: same origin for the page and /io, nothing else exposed.
import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { request } from 'node:http';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';

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

describe('gateway HTTP', () => {
  let gw: RunningGateway;
  beforeAll(async () => {
    const root = mkdtempSync(join(tmpdir(), 'rungsmith-dist-'));
    mkdirSync(join(root, 'dist/assets'), { recursive: true });
    writeFileSync(join(root, 'dist/index.html'), '<!doctype html><title>Rungsmith</title>');
    writeFileSync(join(root, 'dist/assets/app.js'), 'console.log(1)');
    writeFileSync(join(root, 'secret.txt'), 'do not serve');
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
});
