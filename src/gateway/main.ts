// `npm start` / `npx rungsmith-gateway`: one process on 127.0.0.1 serving the app and /io.
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync, statSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { checkPlant, loadConfigFile, resolveConfig, type ResolvedConfig } from './config';
import { ConfigError } from './configTypes';
import { startGateway, type RunningGateway } from './gateway';
import { SHUTDOWN_SAFE_DEADLINE_MS } from './ioHub';

/** Exit status when a device did not acknowledge the safe state at shutdown. */
const SAFE_STATE_UNCONFIRMED = 3;

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');

const USAGE = `usage: rungsmith-gateway [--port N] [--config FILE] [--sim-port N] [--plant NAME] [--plant-watchdog MS] [--build-if-needed] [--no-app]
  --port N            HTTP + WebSocket port on 127.0.0.1 (default: PORT or 8080; 0 picks a free port)
  --config FILE       JSON config naming Modbus TCP devices (docs/GATEWAY-CONFIG.md)
  --sim-port N        Modbus TCP port of the simulated device on 127.0.0.1 (default 5020, 0: free port)
  --plant NAME        the simulated device is that machine (docs/PLANTS.md), advancing in real time:
                      a Modbus master (a real PLC) writes its actuators (coils) and reads its sensors
  --plant-watchdog MS with --plant: no write to the actuators for MS ms (default 1000, 0: off) and
                      the outputs the master wrote fall OFF, as an I/O coupler's watchdog does
  --build-if-needed   run "vite build" when dist/ is missing or older than the sources
  --no-app            serve only the WebSocket endpoint /io
env: RUNGSMITH_TOKEN fixes the token (else config "token", else a random 256-bit one)`;

interface Args {
  port?: number;
  config?: string;
  simPort?: number;
  plant?: string;
  plantWatchdog?: number;
  build: boolean;
  app: boolean;
}

function parseArgs(argv: readonly string[]): Args {
  const args: Args = { build: false, app: true };
  const int = (flag: string, text: string | undefined) => {
    const n = Number(text);
    if (text === undefined || !Number.isInteger(n) || n < 0 || n > 65535) throw new ConfigError(flag, `needs a port number 0-65535, got ${JSON.stringify(text ?? '')}`);
    return n;
  };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--port') args.port = int('--port', argv[++i]);
    else if (a === '--sim-port') args.simPort = int('--sim-port', argv[++i]);
    else if (a === '--plant') {
      const name = argv[++i];
      if (!name) throw new ConfigError('--plant', 'needs a machine name (rungsmith plants lists them)');
      args.plant = name;
    }
    else if (a === '--plant-watchdog') {
      const text = argv[++i];
      const ms = Number(text);
      if (text === undefined || !Number.isInteger(ms) || ms < 0 || ms > 60_000 || (ms > 0 && ms < 100))
        throw new ConfigError('--plant-watchdog', `needs 0 (off) or 100 to 60000 ms, got ${JSON.stringify(text ?? '')}`);
      args.plantWatchdog = ms;
    } else if (a === '--config') {
      const file = argv[++i];
      if (!file) throw new ConfigError('--config', 'needs a file name');
      args.config = file;
    } else if (a === '--build-if-needed') args.build = true;
    else if (a === '--no-app') args.app = false;
    else if (a === '--help' || a === '-h') {
      process.stdout.write(USAGE + '\n');
      process.exit(0);
    } else throw new ConfigError(String(a), `unknown option\n${USAGE}`);
  }
  return args;
}

function newestMtime(path: string): number {
  if (!existsSync(path)) return 0;
  const st = statSync(path);
  if (!st.isDirectory()) return st.mtimeMs;
  return readdirSync(path).reduce((m, name) => Math.max(m, newestMtime(join(path, name))), st.mtimeMs);
}

function buildIfNeeded(): void {
  const built = existsSync(join(ROOT, 'dist/index.html')) ? statSync(join(ROOT, 'dist/index.html')).mtimeMs : 0;
  const sources = Math.max(...['src', 'public', 'index.html', 'vite.config.ts', 'package.json'].map((p) => newestMtime(join(ROOT, p))));
  if (built >= sources) return;
  process.stderr.write(built ? 'dist/ is older than the sources: building the app…\n' : 'dist/ is missing: building the app…\n');
  const vite = join(ROOT, 'node_modules/vite/bin/vite.js');
  const r = spawnSync(process.execPath, [vite, 'build', '--logLevel', 'warn'], { cwd: ROOT, stdio: ['ignore', 2, 2] });
  if (r.status !== 0) throw new Error('vite build failed; see the messages above');
}

/** A write to a closed terminal or pipe. */
const isBrokenPipe = (e: unknown) => typeof e === 'object' && e !== null && 'code' in e && (e.code === 'EPIPE' || e.code === 'EIO' || e.code === 'ERR_STREAM_DESTROYED');

async function main(): Promise<void> {
  const args = parseArgs(process.argv.slice(2));
  const base: ResolvedConfig = args.config ? loadConfigFile(args.config) : resolveConfig({});
  const withPort: ResolvedConfig = args.simPort !== undefined ? { ...base, simulated: { ...base.simulated, modbusPort: args.simPort } } : base;
  const withPlant: ResolvedConfig = args.plant !== undefined ? { ...withPort, simulated: { ...withPort.simulated, plant: args.plant } } : withPort;
  const config: ResolvedConfig =
    args.plantWatchdog !== undefined ? { ...withPlant, simulated: { ...withPlant.simulated, masterWatchdogMs: args.plantWatchdog } } : withPlant;
  if (args.plant !== undefined) checkPlant(config, args.config ? `--plant (with --config ${args.config})` : '--plant');
  if (args.build && args.app) buildIfNeeded();
  const envPort = process.env.PORT !== undefined && process.env.PORT !== '' ? Number(process.env.PORT) : undefined;
  if (envPort !== undefined && (!Number.isInteger(envPort) || envPort < 0 || envPort > 65535)) throw new ConfigError('PORT', `is not a port number: ${process.env.PORT}`);
  const port = args.port ?? envPort ?? config.port ?? 8080;
  const token = process.env.RUNGSMITH_TOKEN || undefined;
  if (token !== undefined && token.length < 16) throw new ConfigError('RUNGSMITH_TOKEN', 'needs at least 16 characters');
  // A closed terminal or a dropped SSH session leaves stdout/stderr as broken pipes (EPIPE, EIO):
  // a log line must never throw or end the process before the safe write.
  for (const stream of [process.stdout, process.stderr]) stream.on('error', () => undefined);
  const log = (line: string) => {
    try {
      if (process.stderr.writable) process.stderr.write(`[gateway] ${line}\n`);
    } catch {
      // the log is lost; the shutdown is not
    }
  };
  const distDir = args.app ? join(ROOT, 'dist') : null;

  const running: { gw?: RunningGateway } = {};
  let exiting = false;
  const shutdown = async (why: string, code: number) => {
    if (exiting) return;
    exiting = true;
    log(`${why}: stopping, writing the safe state as the last write, then exiting`);
    // Past the safe write's own deadline: the process must end even if a device never answers.
    const hardStop = setTimeout(() => {
      log('shutdown did not finish: exiting WITHOUT confirmation that the outputs are in the safe state');
      process.exit(SAFE_STATE_UNCONFIRMED);
    }, SHUTDOWN_SAFE_DEADLINE_MS + 3000);
    let exitCode = code;
    try {
      const report = await running.gw?.close();
      for (const d of report?.devices ?? []) {
        if (d.acknowledged) log(`device "${d.id}": safe state written and acknowledged`);
        else log(`device "${d.id}": safe state NOT confirmed${d.error ? ` (${d.error})` : ''}: its outputs may still be ON; check the device (its own communication watchdog should switch them off)`);
      }
      if (report && !report.safe) exitCode = SAFE_STATE_UNCONFIRMED;
    } catch (e) {
      log(`shutdown failed: ${e instanceof Error ? e.message : String(e)}`);
      exitCode = SAFE_STATE_UNCONFIRMED;
    } finally {
      clearTimeout(hardStop);
      process.exit(exitCode);
    }
  };
  // Every catchable way to end the process runs the same shutdown: Ctrl+C, kill, a closed terminal
  // or dropped SSH session (SIGHUP), Ctrl+\ (SIGQUIT), and on Windows Ctrl+Break / a closed console.
  const signals: NodeJS.Signals[] = ['SIGINT', 'SIGTERM', 'SIGHUP', 'SIGQUIT'];
  if (process.platform === 'win32') signals.push('SIGBREAK');
  for (const signal of signals) process.on(signal, () => void shutdown(signal, 0));
  process.on('uncaughtException', (e) => {
    if (exiting && isBrokenPipe(e)) return; // a log write to a closed terminal during shutdown
    log(`uncaught error: ${e.stack ?? e.message}`);
    void shutdown('uncaught error', 1);
  });
  process.on('unhandledRejection', (e) => {
    log(`unhandled rejection: ${e instanceof Error ? (e.stack ?? e.message) : String(e)}`);
    void shutdown('unhandled rejection', 1);
  });

  const gw = await startGateway({ port, config, distDir, token, log });
  running.gw = gw;
  const sim = gw.simulated?.modbusServerPort;
  log(gw.simulated ? `simulated I/O device (16 DI, 16 DO, 4 AI, 4 AO)${sim ? `, Modbus TCP on 127.0.0.1:${sim}` : ''}${config.simulated.plant ? `; it is the machine "${config.simulated.plant}" (its actuators are the coils a Modbus master writes, docs/PLANTS.md; ${config.simulated.masterWatchdogMs > 0 ? `they fall OFF after ${config.simulated.masterWatchdogMs} ms without a write, --plant-watchdog` : 'no watchdog: --plant-watchdog 0'})` : ''}` : `${config.devices.length} Modbus TCP device(s)`);
  try {
    process.stdout.write(`Rungsmith gateway: open ${gw.url}\n`);
  } catch {
    log(`open ${gw.url}`);
  }
}

main().catch((e: unknown) => {
  process.stderr.write(`rungsmith-gateway: ${e instanceof Error ? e.message : String(e)}\n`);
  process.exit(2);
});
