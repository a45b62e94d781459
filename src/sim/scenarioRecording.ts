// The scan history as a scenario: what the session tracks since the last cold start to tell whether
// the recorded scans can replay as they ran, and the helpers a scenario replay runs with.
import type { Plc } from '../engine/api';
import type { Project } from '../model/project';
import type { HistoryRecorder } from './historyRecorder';
import { isProgramView, withView } from './layout';
import type { SimLayout } from './protocol';

/** Since the last cold start: the first online change or warm restart, and the names forced. */
export interface SinceColdStart {
  interruptedAt?: { scan: number; what: string };
  forced: Set<string>;
}

/**
 * Why the recorded scans cannot become a scenario that replays as it ran, or undefined. A scenario
 * starts from a cold start and only sets inputs, so the recording must start at scan 1 after a cold
 * start, with no online change or warm restart and no forces since.
 */
export function scenarioRecordingProblem(sinceColdStart: SinceColdStart, recorder: HistoryRecorder, from: number | undefined): string | undefined {
  const again = 'Press Reset (cold restart), release the forces, run and switch the inputs, then record again.';
  const { interruptedAt, forced } = sinceColdStart;
  if (interruptedAt)
    return `A scenario replays from a cold start, and ${interruptedAt.what} at scan ${interruptedAt.scan} changed the program or its state since the last one: the scenario would not replay as it ran. ${again}`;
  if (forced.size)
    return `Forces were active while recording (${[...forced].join(', ')}): a scenario sets inputs and cannot force, so it would not replay as it ran. ${again}`;
  const first = Math.max(from ?? 1, recorder.history.first ?? 1);
  if (first !== 1)
    return `A scenario replays from a cold start, but the recording starts at scan ${first} (${from && from > 1 ? 'the range asked' : 'the oldest scans no longer fit in the history'}), not at scan 1. ${again}`;
  return undefined;
}

/** The layout with its network fields on the program's own (first) body, as the history records it. */
export function programLayout(project: Project, layout: SimLayout): SimLayout {
  if (isProgramView(layout)) return layout;
  const first = layout.programs?.[0]?.instance;
  return withView(project, layout, { pou: layout.pou, ...(first !== undefined ? { instance: first } : {}) });
}

/** The PLC with its clock set before each scan (scan k at (k - 1) x cycle), for runPrepared. */
export function plcScanWithClock(plc: Plc, before: (scan: number) => void): Plc {
  let k = 0;
  return new Proxy(plc, {
    get(target, key) {
      if (key === 'scan')
        return () => {
          before(++k);
          return target.scan();
        };
      const v = Reflect.get(target, key, target) as unknown;
      return typeof v === 'function' ? (v as (...a: unknown[]) => unknown).bind(target) : v;
    },
  });
}
