// npm run bench:gateway — the gateway on loopback against a Modbus TCP "plant" in another process
// whose coils are wired back to its discrete inputs (a loop-back cable).
//  1. round trip: browser-message `outputs` -> Modbus write -> Modbus read -> browser-message `inputs`
//  2. sustained outputs at 10 ms scans with 256 points: achieved rate and the device request backlog
// Last line: bench:gateway p99-ms=<n> poll-ms=<n> backlog=<n>
import { spawn } from 'node:child_process';
import { createServer, type AddressInfo } from 'node:net';
import WebSocket from 'ws';
import { resolveConfig } from '../src/gateway/config';
import { startGateway } from '../src/gateway/gateway';

const POLL_MS = 20;
const POINTS = 256;
const ROUND_TRIPS = 200;
const SCAN_MS = 10;
const SUSTAINED_MS = 5000;

const PLANT = `
const { ServerTCP } = require('modbus-serial');
const coils = new Array(${POINTS}).fill(false);
const check = (a) => { if (a < 0 || a >= ${POINTS}) throw { modbusErrorCode: 2 }; };
const server = new ServerTCP({
  getCoil: (a) => (check(a), coils[a]),
  getDiscreteInput: (a) => (check(a), coils[a]),
  setCoil: (a, v) => { check(a); coils[a] = v; },
}, { host: '127.0.0.1', port: Number(process.argv[1]), unitID: 255 });
server.on('initialized', () => console.log('READY'));
server.on('socketError', () => {});
`;

function freePort(): Promise<number> {
  return new Promise((resolve) => {
    const s = createServer().listen(0, '127.0.0.1', () => {
      const { port } = s.address() as AddressInfo;
      s.close(() => resolve(port));
    });
  });
}

const quantile = (sorted: number[], q: number) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))] ?? NaN;
const ms = (n: number) => n.toFixed(2);

async function main() {
  const plantPort = await freePort();
  const plant = spawn(process.execPath, ['-e', PLANT, String(plantPort)], { stdio: ['ignore', 'pipe', 'inherit'] });
  await new Promise<void>((resolve) => plant.stdout.once('data', () => resolve()));

  const config = resolveConfig({
    watchdogMs: 1000,
    devices: [
      {
        id: 'plant',
        host: '127.0.0.1',
        port: plantPort,
        pollMs: POLL_MS,
        timeoutMs: 1000,
        points: [
          { address: '%QX0.0', count: POINTS, table: 'coils', register: 0 },
          { address: '%IX0.0', count: POINTS, table: 'discreteInputs', register: 0 },
        ],
      },
    ],
  });
  const gw = await startGateway({ port: 0, config, distDir: null });
  const device = gw.hub.devices[0]!;

  const ws = new WebSocket(`ws://127.0.0.1:${gw.port}/io`);
  const waiters: ((m: { t: string; values?: Record<string, unknown> }) => void)[] = [];
  ws.on('message', (d) => {
    const m = JSON.parse(String(d)) as { t: string; values?: Record<string, unknown> };
    waiters.forEach((w) => w(m));
  });
  await new Promise((r) => ws.once('open', r));
  const next = (pred: (m: { t: string; values?: Record<string, unknown> }) => boolean) =>
    new Promise<void>((resolve) => {
      const w = (m: { t: string; values?: Record<string, unknown> }) => {
        if (pred(m)) {
          waiters.splice(waiters.indexOf(w), 1);
          resolve();
        }
      };
      waiters.push(w);
    });
  const online = next((m) => m.t === 'status' && JSON.stringify(m).includes('"state":"online"'));
  ws.send(JSON.stringify({ v: 1, t: 'hello', token: gw.token, role: 'controller' }));
  await online;
  // The gateway starts disarmed: arm, as Run does.
  const armed = next((m) => m.t === 'status' && JSON.stringify(m).includes('"armed":true'));
  ws.send(JSON.stringify({ v: 1, t: 'arm' }));
  await armed;

  const image = (on: boolean) => {
    const values: Record<string, boolean> = {};
    for (let i = 0; i < POINTS; i++) values[`%QX${Math.floor(i / 8)}.${i % 8}`] = i === 0 ? on : i % 3 === 0;
    return values;
  };
  let seq = 0;
  const send = (values: Record<string, boolean>) => ws.send(JSON.stringify({ v: 1, t: 'outputs', seq: ++seq, values }));

  // 1. Round trips: flip %QX0.0 and wait for %IX0.0 to come back over the plant's loop-back.
  const rtts: number[] = [];
  const writeLegs: number[] = [];
  for (let i = 0; i < ROUND_TRIPS; i++) {
    const on = i % 2 === 0;
    const back = next((m) => m.t === 'inputs' && m.values?.['%IX0.0'] === on);
    const t0 = performance.now();
    void next((m) => m.t === 'written' && m.values?.['%QX0.0'] === on).then(() => writeLegs.push(performance.now() - t0));
    send(image(on));
    await back;
    rtts.push(performance.now() - t0);
    await new Promise((r) => setTimeout(r, Math.random() * POLL_MS)); // de-correlate from the poll phase
  }
  rtts.sort((a, b) => a - b);
  writeLegs.sort((a, b) => a - b);
  console.log(`write leg outputs -> Modbus write done -> written: median ${ms(quantile(writeLegs, 0.5))} ms, p99 ${ms(quantile(writeLegs, 0.99))} ms`);
  const median = quantile(rtts, 0.5);
  const p99 = quantile(rtts, 0.99);
  console.log(`round trip outputs -> Modbus write -> Modbus read -> inputs, ${ROUND_TRIPS} samples, poll ${POLL_MS} ms: median ${ms(median)} ms, p99 ${ms(p99)} ms, max ${ms(rtts[rtts.length - 1] ?? NaN)} ms`);

  // 2. Sustained: a full 256-point output image every 10 ms scan, changing every scan.
  let sent = 0;
  let maxDepth = 0;
  const depths: number[] = [];
  const t0 = performance.now();
  const scan = setInterval(() => {
    send(image(sent % 2 === 0));
    sent++;
  }, SCAN_MS);
  const sampler = setInterval(() => {
    const d = device.queueDepth();
    depths.push(d);
    maxDepth = Math.max(maxDepth, d);
  }, 50);
  await new Promise((r) => setTimeout(r, SUSTAINED_MS));
  clearInterval(scan);
  clearInterval(sampler);
  const elapsed = (performance.now() - t0) / 1000;
  const half = Math.floor(depths.length / 2);
  const avg = (xs: number[]) => xs.reduce((a, b) => a + b, 0) / Math.max(1, xs.length);
  const backlog = device.queueDepth();
  console.log(
    `sustained: ${sent} output images of ${POINTS} points in ${elapsed.toFixed(2)} s = ${(sent / elapsed).toFixed(0)} scans/s; ` +
      `device queue depth avg first half ${avg(depths.slice(0, half)).toFixed(2)}, second half ${avg(depths.slice(half)).toFixed(2)}, max ${maxDepth}, at end ${backlog}; ws buffered ${ws.bufferedAmount} B`,
  );
  ws.send(JSON.stringify({ v: 1, t: 'stop' }));
  ws.close();
  await gw.close();
  plant.kill();
  console.log(`bench:gateway p99-ms=${ms(p99)} poll-ms=${POLL_MS} backlog=${backlog}`);
}

main().catch((e: unknown) => {
  console.error(e);
  process.exit(1);
});
