#!/usr/bin/env node
// `npm test`: the type check, lint, build, unit tests and browser tests, in three stages:
//
//   1. tsc --noEmit, eslint . and vite build, side by side (no deadlines in them: they only need CPU);
//   2. the unit tests (vitest.config.ts: two files at a time);
//   3. the browser tests (vitest.e2e.config.ts, against the server `npm start` runs), when the
//      build passed.
//
// The unit and browser tests wait on deadlines (a gateway answering, a page painting), so they do
// not run beside each other: on a busy 2-core machine that made both miss deadlines.
// Every phase runs whatever happens to the others (only the browser tests need the build), so
// one run reports every failure; the exit code is 1 when any phase failed.
//
// Output: each line is prefixed with its phase ("unit │ …") as it comes; at the end, the output of
// every failed phase is printed again whole, then a table of the phases with their times.
// `npm run typecheck`, `npm run lint`, `npm run test:unit` and `npm run test:e2e` run one part alone.
import { spawn } from 'node:child_process';
import { performance } from 'node:perf_hooks';

const npx = process.platform === 'win32' ? 'npx.cmd' : 'npx';

/** The stages, in order; the phases of a stage run side by side. */
const stages = [
  [
    { name: 'typecheck', cmd: [npx, 'tsc', '-p', 'tsconfig.json', '--noEmit'] },
    { name: 'lint', cmd: [npx, 'eslint', '.'] },
    { name: 'build', cmd: [npx, 'vite', 'build'] },
  ],
  [{ name: 'unit', cmd: [npx, 'vitest', 'run'] }],
  [{ name: 'e2e', cmd: [npx, 'vitest', 'run', '-c', 'vitest.e2e.config.ts'], needs: 'build' }],
];

const width = Math.max(...stages.flat().map((p) => p.name.length));
const color = process.stdout.isTTY ? { FORCE_COLOR: '1' } : {};
const children = new Set();

/** Runs one phase, echoing its lines with a prefix; resolves with its exit code, time and output. */
function run(phase) {
  return new Promise((resolve) => {
    const started = performance.now();
    const child = spawn(phase.cmd[0], phase.cmd.slice(1), { stdio: ['ignore', 'pipe', 'pipe'], env: { ...process.env, ...color } });
    children.add(child);
    const prefix = `${phase.name.padEnd(width)} │ `;
    let output = '';
    const echo = (stream) => {
      let partial = '';
      stream.setEncoding('utf8');
      stream.on('data', (chunk) => {
        output += chunk;
        const lines = (partial + chunk).split('\n');
        partial = lines.pop() ?? '';
        if (lines.length) process.stdout.write(lines.map((l) => prefix + l).join('\n') + '\n');
      });
      stream.on('end', () => {
        if (partial) process.stdout.write(prefix + partial + '\n');
      });
    };
    echo(child.stdout);
    echo(child.stderr);
    const done = (code) => {
      children.delete(child);
      resolve({ ...phase, code, seconds: (performance.now() - started) / 1000, output });
    };
    child.once('error', (e) => {
      output += String(e);
      done(-1);
    });
    child.once('close', (code, signal) => done(code ?? (signal ? 128 : -1)));
  });
}

for (const signal of ['SIGINT', 'SIGTERM']) {
  process.on(signal, () => {
    for (const c of children) c.kill(signal);
    process.exit(130);
  });
}

const started = performance.now();
const results = [];
for (const stage of stages) {
  results.push(
    ...(await Promise.all(
      stage.map((phase) => {
        // The browser tests need the build: when it failed, they are not run.
        if (phase.needs && results.some((r) => r.name === phase.needs && r.code !== 0)) {
          return { ...phase, code: -1, seconds: 0, output: `not run: ${phase.needs} failed\n`, skipped: true };
        }
        return run(phase);
      }),
    )),
  );
}
const total = (performance.now() - started) / 1000;

const failed = results.filter((r) => r.code !== 0);
for (const r of failed) {
  process.stdout.write(`\n──── ${r.name} (${r.cmd.slice(1).join(' ')}) failed; its output: ────\n${r.output}\n`);
}
process.stdout.write('\n');
for (const r of results) {
  const status = r.skipped ? 'not run' : r.code === 0 ? 'passed' : `FAILED (exit ${r.code})`;
  process.stdout.write(`${r.name.padEnd(width)}  ${r.seconds.toFixed(1).padStart(6)} s  ${status}\n`);
}
process.stdout.write(`${'total'.padEnd(width)}  ${total.toFixed(1).padStart(6)} s  ${failed.length ? `${failed.length} failed` : 'all passed'}\n`);
process.exit(failed.length ? 1 : 0);
