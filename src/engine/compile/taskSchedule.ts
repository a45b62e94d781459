// The tasks of a configuration as MATIEC compiles a resource (stage4/generate_c/generate_c.cc):
// the common tick is the greatest common divisor of the task intervals (`common_ticktime__`,
// calculate_common_ticktime_c: every INTERVAL counts, an event task's too); each tick, a cyclic
// task's flag is `!(tick % (interval / common_ticktime))`, an event task's the Q of an R_TRIG fed
// with its SINGLE variable (generate_c_resources_c, task_initialization_c), and the program
// instances run in their declaration order when their task's flag is set. Priorities order nothing:
// the runtime runs the whole resource in one thread.
import type { Task } from '../../model/project';
import type { TaskRate, TaskSchedule } from '../api';
import type { BodyInfo } from './flatten';

/** Intervals are compared in whole microseconds (a file may give T#500us). */
const US = 1000;

function gcd(a: number, b: number): number {
  while (b !== 0) [a, b] = [b, a % b];
  return a;
}

/** The common tick, ms, of cyclic intervals given in ms (0 when there is none). */
export function commonTickMs(intervalsMs: readonly number[]): number {
  let g = 0;
  for (const ms of intervalsMs) {
    const us = Math.round(ms * US);
    if (us > 0) g = g === 0 ? us : gcd(us, g);
  }
  return g / US;
}

/**
 * The schedule of the tasks that run program instances, in the project's order. A task without
 * programs does not count in the tick (MATIEC counts it: its ticks would run nothing).
 */
export function taskSchedule(tasks: readonly Task[]): TaskSchedule {
  const running = tasks.filter((t) => t.programs.length > 0);
  const tickMs = commonTickMs(running.map((t) => t.cycleMs));
  const rates: TaskRate[] = running.map((t) => ({
    name: t.name,
    intervalMs: t.cycleMs,
    every: t.single ? 0 : tickMs > 0 ? Math.max(1, Math.round((t.cycleMs * US) / (tickMs * US))) : 1,
    ...(t.single ? { single: t.single } : {}),
    instances: t.programs.map((p) => p.instance),
  }));
  // No interval at all (only event tasks without one): MATIEC refuses the configuration (LD-E20).
  return { tickMs, tasks: rates, multiRate: tickMs > 0 && rates.some((r) => r.every !== 1) };
}

/** True when an event task runs programs: the tasks then run as a configuration, even one instance. */
export const hasEventTask = (tasks: readonly Task[]): boolean => tasks.some((t) => t.single && t.programs.length > 0);

/**
 * In words, for the Tasks dialog, the README's example and the CLI: "Fast runs every tick (10 ms);
 * Slow every 3rd tick (30 ms); E runs when StartPulse rises".
 */
export function describeSchedule(s: TaskSchedule): string {
  const parts = s.tasks.map((t, i) => {
    if (t.single) return `${t.name} runs when ${t.single} rises`;
    const when = t.every === 1 ? 'every tick' : `every ${ordinal(t.every)} tick`;
    return `${t.name}${i === 0 || s.tasks[i - 1]!.single ? ' runs' : ''} ${when} (${t.intervalMs} ms)`;
  });
  return `${parts.join('; ')}`;
}

/**
 * Why a cycle the user asks for (`requested`, ms) cannot apply: the tasks run on their common tick
 * (`the tasks run at different intervals (...), so a scan is their common tick of 10 ms`); undefined
 * when it can (one rate, or the request is the tick). Shared by scenarios' `# cycle:` and `--cycle`.
 */
export function tickConflict(s: TaskSchedule | undefined, requested: number | undefined): string | undefined {
  if (!s?.multiRate || requested === undefined || requested === s.tickMs) return undefined;
  return `the tasks run at different intervals (${describeSchedule(s)}), so a scan is their common tick of ${s.tickMs} ms`;
}

function ordinal(n: number): string {
  const tens = n % 100;
  const suffix = tens >= 11 && tens <= 13 ? 'th' : n % 10 === 1 ? 'st' : n % 10 === 2 ? 'nd' : n % 10 === 3 ? 'rd' : 'th';
  return `${n}${suffix}`;
}

/** The program (body 0..programs-1) a body runs in: its caller's, up to the program. */
export function programOf(bodies: readonly BodyInfo[], body: BodyInfo): BodyInfo {
  let root = body;
  while (root.parent >= 0) root = bodies[root.parent]!;
  return root;
}
