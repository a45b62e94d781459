// Starts `vite preview` on the built app (dist/) on a loopback port and checks for Chromium.
import { existsSync } from 'node:fs';
import { preview, type PreviewServer } from 'vite';
import type { TestProject } from 'vitest/node';
import { CHROMIUM_PATH } from './browser';

let server: PreviewServer | undefined;

export async function setup(project: TestProject) {
  if (!existsSync(CHROMIUM_PATH)) {
    throw new Error(
      `Chromium not found at ${CHROMIUM_PATH}. Browser tests need Debian's chromium: run "sudo apt-get install -y chromium" (never "npx playwright install").`,
    );
  }
  if (!existsSync('dist/index.html')) throw new Error('dist/ is missing: run "npm run build" (npm run test:e2e does it).');
  server = await preview({ preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'warn' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('preview server has no port');
  project.provide('appUrl', `http://127.0.0.1:${address.port}/`);
}

export async function teardown() {
  await new Promise<void>((resolve) => server?.httpServer.close(() => resolve()) ?? resolve());
}

declare module 'vitest' {
  export interface ProvidedContext {
    appUrl: string;
  }
}
