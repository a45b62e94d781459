// Issue 10, "Done means": a controller drives outputs at 100 Hz through the real gateway process
// while the Modbus device (Debian's pymodbus) is killed and restarted, slowed to 2 s per answer or
// made to answer with exceptions, and SIGTERM arrives at a random moment. Issue 21 adds SIGHUP
// (half of them with stdin/stdout/stderr closed first, as a closed terminal leaves them) and SIGQUIT
// as the ending signal, a second Modbus master (mbpoll) writing the coils, and a device slowed to
// 5x the timeout during STOP, a watchdog trip or the controller disconnecting. In every run:
//  - the process exits 0 (every device acknowledged the safe state) and the device's outputs are 0;
//  - the last write the device saw is the safe image (nothing was dispatched after it);
//  - no write is torn (coils of one scan with the register of another);
//  - after a device restart, nothing but zeros is written until the controller armed again;
//  - with a second master, no coil flips more than once per poll by this gateway's writes;
//  - slowed during STOP, trip or disconnect, the safe image reaches the device while it is still slow;
//  - without a second master, nothing is taken for one (no other-master disarm).
// The random sequence is seeded (printed), so a failing run can be replayed with FAULT_SEED.
import { spawn } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createInterface } from 'node:readline';
import { afterAll, describe, expect, it } from 'vitest';
import { freeLoopbackPort } from '../../src/gateway/modbusLib';
import { coilFlips, mbpoll, mostFlipsWithin, PyModbusServer, readWriteLog, TestClient, type LoggedWrite } from './helpers';

const RUNS = Number(process.env.FAULT_RUNS ?? 52);
const LANES = 2;
const COILS = 8;

type Fault = 'none' | 'kill' | 'slow' | 'exception' | 'second-master' | 'slow-stop' | 'slow-trip' | 'slow-disconnect';
const FAULTS: readonly Fault[] = ['none', 'kill', 'slow', 'exception', 'second-master', 'slow-stop', 'slow-trip', 'slow-disconnect'];
/** The ending signal of run n (in turn, so every kind is in every suite of 3 runs or more). */
const SIGNALS = ['SIGTERM', 'SIGHUP', 'SIGQUIT'] as const;
const POLL_MS = 20;
/** The second master's image: every coil ON (the program's image in those runs is 165, never all ON). */
const OTHER = Array.from({ length: COILS }, () => '1');
const isOthers = (w: LoggedWrite) => w.table === 'co' && w.address === 0 && w.values.length === COILS && w.values.every((v) => v === 1);

/** A small seeded generator (mulberry32): the same seed gives the same runs. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

/** The output image of scan generation g: coil i is bit i of g, %QW0 is g (g is 1..255, never all OFF). */
function image(g: number): Record<string, boolean | number> {
  const values: Record<string, boolean | number> = { '%QW0': g };
  for (let i = 0; i < COILS; i++) values[`%QX0.${i}`] = ((g >> i) & 1) === 1;
  return values;
}
const genOfCoils = (bits: readonly number[]) => bits.reduce((g, b, i) => g | ((b ? 1 : 0) << i), 0);

interface RunResult {
  readonly fault: Fault;
  readonly signal: (typeof SIGNALS)[number];
  readonly closedPipes: boolean;
  /** slow-* faults: whether the coils read OFF while the device was still slow. */
  readonly safeWhileSlow: boolean | undefined;
  readonly otherWrites: number;
  readonly exitCode: number | null;
  readonly finalCoils: number[];
  readonly finalRegister: number;
  readonly writes: LoggedWrite[];
  readonly restartedAt: number | undefined;
  readonly killedAt: number | undefined;
  readonly arms: number[];
  readonly stderr: string;
  /** When the ending signal was sent: from then on the gateway writes its final safe image. */
  readonly signalledAt: number;
}

class Lane {
  plant!: PyModbusServer;
  modbusPort = 0;
  readonly log: string;
  private readonly dir: string;
  constructor(readonly id: number) {
    this.dir = mkdtempSync(join(tmpdir(), `rungsmith-fault-${id}-`));
    this.log = join(this.dir, 'writes.log');
  }

  async start(): Promise<void> {
    this.modbusPort = await freeLoopbackPort();
    this.plant = await PyModbusServer.start(this.modbusPort, this.log);
  }

  async run(n: number, rnd: () => number): Promise<RunResult> {
    const fault = FAULTS[Math.floor(rnd() * FAULTS.length)] ?? 'none';
    const signal = SIGNALS[n % SIGNALS.length] ?? 'SIGTERM';
    const closedPipes = signal === 'SIGHUP' && Math.floor(n / SIGNALS.length) % 2 === 1;
    const config = join(this.dir, `gateway-${n}.json`);
    writeFileSync(
      config,
      JSON.stringify({
        watchdogMs: 1000,
        devices: [
          {
            id: 'plant',
            host: '127.0.0.1',
            port: this.modbusPort,
            pollMs: POLL_MS,
            timeoutMs: 200,
            points: [{ address: '%IX0.0' }, { address: `%QX0.0`, count: COILS }, { address: '%QW0' }],
          },
        ],
      }),
    );
    const startedAt = Date.now();
    const proc = spawn(process.execPath, ['bin/rungsmith-gateway.mjs', '--port', '0', '--config', config, '--no-app'], { stdio: ['pipe', 'pipe', 'pipe'] });
    let stderr = '';
    proc.stderr?.on('data', (d: Buffer) => (stderr += d.toString()));
    const exited = new Promise<number | null>((resolve) => proc.once('exit', (code) => resolve(code)));
    const line = await new Promise<string>((resolve, reject) => {
      createInterface({ input: proc.stdout! }).once('line', resolve);
      proc.once('exit', () => reject(new Error(`gateway exited before printing its URL:\n${stderr}`)));
    });
    const m = /open http:\/\/127\.0\.0\.1:(\d+)\/#token=(\S+)$/.exec(line);
    if (!m) throw new Error(`unexpected first line: ${line}`);
    const c = await TestClient.hello(Number(m[1]), m[2] ?? '', 'controller');
    const arms: number[] = [];
    await c.arm(10_000);
    arms.push(Date.now());

    // The program: a new image every 10 ms (a constant one with a second master, so any flip is
    // the masters', not the program's). The operator: re-arms a while after any disarm.
    let g = 0;
    const scans = setInterval(() => {
      g = fault === 'second-master' ? 165 : (g % 255) + 1;
      c.send({ t: 'outputs', seq: g, values: image(g) });
    }, 10);
    let operatorBusy = false;
    let operatorAway = false;
    const operator = setInterval(() => {
      const s = c.lastStatus();
      if (operatorAway || operatorBusy || !s || s.armed || !s.devices.every((d) => d.state === 'online')) return;
      operatorBusy = true;
      setTimeout(
        () => {
          arms.push(Date.now());
          c.send({ t: 'arm' });
          operatorBusy = false;
        },
        50 + rnd() * 250,
      );
    }, 25);

    // The fault, somewhere in the run; SIGTERM at a random moment (possibly while the fault lasts).
    const sigtermAfter = 150 + rnd() * 1350;
    const faultAfter = rnd() * sigtermAfter;
    const faultLasts = 200 + rnd() * 1000;
    let killedAt: number | undefined;
    let restartedAt: number | undefined;
    let safeWhileSlow: boolean | undefined;
    let otherWrites = 0;
    const faultDone = (async () => {
      if (fault === 'none') return;
      await sleep(faultAfter);
      if (fault === 'second-master') {
        // Another Modbus master writes every coil ON every 50 ms while the fault lasts.
        const end = Date.now() + faultLasts;
        while (Date.now() < end) {
          await mbpoll(this.modbusPort, ['-t', '0', '-r', '0', '127.0.0.1', ...OTHER]);
          otherWrites++;
          await sleep(50);
        }
      } else if (fault === 'slow-stop' || fault === 'slow-trip' || fault === 'slow-disconnect') {
        // Slowed to 5x the timeout, then STOP / the program stops (lease) / the controller goes away.
        await this.plant.mode('slow', 1000);
        operatorAway = true;
        if (fault === 'slow-stop') c.send({ t: 'stop', seq: 1 });
        else clearInterval(scans);
        if (fault === 'slow-disconnect') c.close();
        const end = Date.now() + 20_000;
        safeWhileSlow = false;
        while (Date.now() < end) {
          if ((await this.plant.get('co', 0, COILS)).every((v) => v === 0) && (await this.plant.get('hr', 0, 1))[0] === 0) {
            safeWhileSlow = true;
            break;
          }
          await sleep(50);
        }
        await this.plant.mode('normal');
      } else if (fault === 'kill') {
        killedAt = Date.now();
        await this.plant.kill();
        await sleep(faultLasts / 2);
        await this.start2();
        restartedAt = Date.now();
      } else {
        await this.plant.mode(fault, 2000);
        await sleep(faultLasts);
        await this.plant.mode('normal');
      }
    })();
    await sleep(sigtermAfter);
    // A second master and the slowed device finish first: the safe image must be the device's last write,
    // and the slow cases are about STOP, trip and disconnect, not shutdown.
    if (fault === 'second-master' || fault.startsWith('slow-')) await faultDone;
    if (closedPipes) {
      proc.stdin.destroy();
      proc.stdout.destroy();
      proc.stderr.destroy();
    }
    const signalledAt = Date.now();
    proc.kill(signal);
    const exitCode = await exited;
    clearInterval(scans);
    clearInterval(operator);
    c.close();
    await faultDone;
    const finalCoils = await this.plant.get('co', 0, COILS);
    const finalRegister = (await this.plant.get('hr', 0, 1))[0] ?? -1;
    const writes = readWriteLog(this.log).filter((w) => w.at >= startedAt);
    return { fault, signal, closedPipes, safeWhileSlow, otherWrites, exitCode, finalCoils, finalRegister, writes, restartedAt, killedAt, arms, stderr, signalledAt };
  }

  /** Restarts the device on the same port (a power cycle: its outputs come back OFF). */
  private async start2(): Promise<void> {
    for (let attempt = 0; ; attempt++) {
      try {
        this.plant = await PyModbusServer.start(this.modbusPort, this.log);
        return;
      } catch (e) {
        if (attempt > 20) throw e;
        await sleep(50);
      }
    }
  }

  async stop(): Promise<void> {
    await this.plant?.kill();
  }
}

/** Every problem a run shows, in words (empty when the run was safe). */
function problems(r: RunResult): string[] {
  const out: string[] = [];
  if (r.exitCode !== 0) out.push(`exit code ${r.exitCode}`);
  if (r.finalCoils.some((v) => v !== 0) || r.finalRegister !== 0) out.push(`outputs left ON: coils ${r.finalCoils.join('')}, %QW0 ${r.finalRegister}`);
  const lastCoils = [...r.writes].reverse().find((w) => w.table === 'co');
  const lastReg = [...r.writes].reverse().find((w) => w.table === 'hr');
  if (lastCoils?.values.some((v) => v !== 0) || lastReg?.values.some((v) => v !== 0)) out.push('the last write was not the safe image');
  for (let i = 0; i + 1 < r.writes.length; i++) {
    const [a, b] = [r.writes[i]!, r.writes[i + 1]!];
    if (r.fault === 'second-master' && isOthers(a)) continue; // the other master writes coils only
    // A single-coil write is this gateway switching off only what it still drove (another master seen).
    if (a.table === 'co' && b.table === 'hr' && a.values.length === COILS && genOfCoils(a.values) !== b.values[0]) {
      out.push(`torn write: coils of scan ${genOfCoils(a.values)} with %QW0 of scan ${b.values[0]}`);
    }
  }
  if (r.fault.startsWith('slow-') && r.safeWhileSlow !== true) out.push('the safe image did not reach the device while it was slow');
  if (r.fault === 'second-master') {
    // This gateway's own writes (not the other master's) while it runs: one flip of a coil per poll,
    // plus at most one more where a foreign write landed between the read-back and the rewrite (the
    // detection's documented limit, docs/gateway-rules.md; seen once on a machine at load 20, when
    // pymodbus logged a stalled burst of requests within one poll). The final safe image after the
    // ending signal is left out: it must be the last write even over the other master's values
    // (checked above), so it may follow a switch-off closely.
    const ours = coilFlips(r.writes, COILS, (w) => !isOthers(w) && w.at < r.signalledAt);
    const most = mostFlipsWithin(ours, POLL_MS);
    if (most > 2) {
      const at = ours.map((times) => times.map((t) => t - r.signalledAt).join(',')).join(' | ');
      out.push(`a coil flipped ${most} times within one poll by this gateway's writes (flip times per coil, ms from the signal: ${at})`);
    }
  } else if (!r.closedPipes && r.stderr.includes('disarmed (other-master)')) {
    out.push('another master was reported where there was none');
  }
  if (r.killedAt !== undefined && r.restartedAt !== undefined) {
    const killedAt = r.killedAt;
    for (const w of r.writes) {
      if (w.at < r.restartedAt || w.values.every((v) => v === 0)) continue;
      if (!r.arms.some((a) => a > killedAt && a < w.at)) out.push(`outputs written after the device restarted without an arm (at +${w.at - r.restartedAt} ms)`);
    }
  }
  return out;
}

describe('fault injection: outputs are never left ON (issue 10)', () => {
  const lanes: Lane[] = [];
  afterAll(async () => {
    await Promise.all(lanes.map((l) => l.stop()));
  });

  it(`${RUNS} runs at 100 Hz with the device killed, slowed, refusing, restarted, a second master, and SIGTERM, SIGHUP or SIGQUIT at random moments`, async () => {
    const seed = Number(process.env.FAULT_SEED ?? Date.now() % 1_000_000);
    for (let i = 0; i < LANES; i++) {
      const lane = new Lane(i);
      await lane.start();
      lanes.push(lane);
    }
    const results: RunResult[] = [];
    await Promise.all(
      lanes.map(async (lane, li) => {
        const rnd = random(seed + li);
        for (let n = li; n < RUNS; n += LANES) results.push(await lane.run(n, rnd));
      }),
    );
    const failures = results.flatMap((r, i) => problems(r).map((p) => `run ${i} (${r.fault}, ${r.signal}${r.closedPipes ? ', pipes closed' : ''}): ${p}\n${r.stderr.split('\n').slice(-6).join('\n')}`));
    const counts = FAULTS.map((f) => `${f} ${results.filter((r) => r.fault === f).length}`).join(', ');
    const signals = SIGNALS.map((s) => `${s} ${results.filter((r) => r.signal === s).length}`).join(', ');
    const all = (r: RunResult) => coilFlips(r.writes, COILS).reduce((n, t) => n + t.length, 0);
    console.log(
      `fault injection, seed ${seed}: ${results.length} runs (${counts}; ${signals}, ${results.filter((r) => r.closedPipes).length} with the pipes closed), ` +
        `${results.reduce((n, r) => n + r.writes.length, 0)} device writes checked; second master: ${results.filter((r) => r.fault === 'second-master').map((r) => `${r.otherWrites} writes, ${all(r)} coil flips`).join('; ')}`,
    );
    expect(failures).toEqual([]);
    expect(results).toHaveLength(RUNS);
    expect(new Set(results.map((r) => r.fault)).size).toBeGreaterThanOrEqual(3);
    if (RUNS >= 30) expect(results.filter((r) => r.signal !== 'SIGTERM').length).toBeGreaterThanOrEqual(10);
  }, 600_000);
});
