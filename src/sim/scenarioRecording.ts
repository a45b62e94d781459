// The scan history as a scenario: what the session tracks since the last cold start to tell whether
// the recorded scans can replay as they ran, and the helpers a scenario replay runs with.
import type { Plc } from '../engine/api';
import type { Project } from '../model/project';
import { addressKey } from '../plant/loop';
import type { PlantModel, PlantPoint } from '../plant/types';
import type { PlantSnapshot } from '../plant/loop';
import { findPlantName, plantNames, plantSpelling, plantValue } from '../plant/values';
import type { Value } from '../model/iecTypes';
import type { ConditionPlant } from './historyRecorder';
import { plantValueType } from '../plant/loop';
import { csvValue } from '../engine/values/literals';
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

/** The machine the recorded scans ran against, as a recorded scenario needs it. */
export interface RecordedPlant {
  readonly id: string;
  readonly model: PlantModel;
  /** The machine after each kept scan of [from, to] in turn (valid only during the call). */
  walk(from: number, to: number, fn: (snapshot: PlantSnapshot) => void): void;
  /** Its points at their addresses (the map it ran with). */
  readonly points: readonly PlantPoint[];
  /** The operator controls held and the faults set in a scan, if still kept. */
  controlsAt(scan: number): { readonly operator: Readonly<Record<string, boolean>>; readonly faults: readonly string[] } | undefined;
}

/** The machine's columns of a recorded scenario: `tank.Start` per operator control, `fault ID` per fault set in the range. */
export interface PlantColumns {
  readonly id: string;
  readonly names: readonly string[];
  /** Each column's value in a scan (pressed / set). */
  at(scan: number): readonly boolean[];
}

/**
 * Recording scans run against a machine: the machine's sensors and operator controls are not the
 * program's inputs to set (the machine sets them: `inputs` without them), its controls and faults
 * are columns of their own, read from the machine's history. Refused (`problem`) when the
 * machine's record does not start at scan 1: it was attached or rewired after the cold start, and
 * a scenario starts it with the program.
 */
export function plantRecording(
  plant: RecordedPlant,
  layout: SimLayout | undefined,
  inputs: readonly string[],
  range: readonly [number, number] | undefined,
): { problem: string } | { inputs: string[]; columns: PlantColumns } {
  if (range && !plant.controlsAt(1))
    return {
      problem: `A scenario starts the machine ${plant.id} with the program at the cold start, but its record starts later (it was chosen or rewired after scan 1). Press Reset (cold restart), run and operate it, then record again.`,
    };
  const wired = new Set(plant.points.filter((p) => p.kind !== 'actuator').map((p) => addressKey(p.address)));
  const located = new Map((layout?.variables ?? []).map((v) => [v.name.toUpperCase(), v.location]));
  const own = inputs.filter((name) => {
    const at = located.get(name.toUpperCase());
    return !(at && wired.has(addressKey(at)));
  });
  const controls = plant.points.filter((p) => p.kind === 'operator').map((p) => p.name);
  const faults = new Set<string>();
  if (range) for (let scan = range[0]; scan <= range[1]; scan++) for (const f of plant.controlsAt(scan)?.faults ?? []) faults.add(f);
  const faultList = [...faults].sort();
  return {
    inputs: own,
    columns: {
      id: plant.id,
      names: [...controls.map((c) => `${plant.id}.${c}`), ...faultList.map((f) => `fault ${f}`)],
      at: (scan) => {
        const c = plant.controlsAt(scan);
        return [...controls.map((n) => c?.operator[n] === true), ...faultList.map((f) => c?.faults.includes(f) === true)];
      },
    },
  };
}

/** The machine's columns of a trace: their names and, per scan of the range, their cells. */
export interface TraceColumns {
  readonly names: readonly string[];
  cells(scan: number): readonly string[];
}

/**
 * A trace's names split into the program's and the machine's (`tank.level`, `tank.Pump`); without
 * names asked for, the program's variables and every quantity of the machine. The machine's cells
 * are worked out in one walk over the range (a step per scan), formatted as `rungsmith simulate
 * --watch` writes them.
 */
export function plantTrace(
  plant: RecordedPlant | undefined,
  names: readonly string[] | undefined,
  programNames: readonly string[],
  range: readonly [number, number] | undefined,
): { program: string[]; columns?: TraceColumns } {
  const asked = names ?? [...programNames, ...(plant ? plantNames(plant.model).filter((n) => n.kind === 'quantity').map((n) => n.name) : [])];
  const own = new Set(programNames.map((n) => n.toUpperCase()));
  const onPlant = (n: string) => plant !== undefined && !own.has(n.toUpperCase()) && findPlantName(plant.model, n) !== undefined;
  const machine = asked.filter(onPlant);
  const program = asked.filter((n) => !onPlant(n));
  if (!plant || machine.length === 0) return { program };
  const types = machine.map((n) => plantValueType(plant.model, n)!);
  const rows = new Map<number, string[]>();
  if (range)
    plant.walk(range[0], range[1], (snap) => {
      rows.set(snap.scan, machine.map((n, j) => csvValue(types[j]!, plantValue(plant.model, snap, n) ?? '')));
    });
  return { program, columns: { names: machine, cells: (scan) => rows.get(scan) ?? machine.map(() => '') } };
}

/** The machine's names for History Find's conditions (`lift.position > 3000`), their values worked out in one walk over the history. */
export function conditionPlant(plant: RecordedPlant | undefined): ConditionPlant | undefined {
  if (!plant) return undefined;
  return {
    spelling: (name) => plantSpelling(plant.model, name),
    values: (names, from, to) => {
      const rows: (readonly Value[])[] = [];
      plant.walk(from, to, (snap) => {
        rows[snap.scan - from] = names.map((n) => plantValue(plant.model, snap, n) ?? 0);
      });
      // A scan the machine's history does not have (it was chosen later): no values, the condition does not hold there.
      return (scan) => rows[scan - from];
    },
  };
}

