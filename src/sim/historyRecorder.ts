// Records every completed scan of the running PLC into a ScanHistory — its times, the input image
// when it changed, and now and then the PLC's complete state (a key) — and rebuilds a recorded scan by
// replay (src/sim/replay.ts) as a frame for the UI, a ScanView for "Why?", a trace CSV or a scenario.
// Recording costs a few counters and two stored times per scan; keys are spaced so that saving them
// stays a small share of scan time while a seek replays at most a few thousand scans.
import type { Plc, PlcImage, PlcProbe, TextTarget, TextTrace } from '../engine/api';
import { explain, flatNetwork, flattenedPou, netOn, type Explanation, type ExplainTarget, type ScanView } from '../engine/explain';
import type { CompiledProgram } from '../engine/plc';
import { csvValue } from '../engine/values/literals';
import type { ElementaryType, Value } from '../model/iecTypes';
import type { Pou, Project } from '../model/project';
import { compileCondition } from './condition';
import { csvRow } from './csv';
import { packNetworks } from './frames';
import { ScanHistory, type HistoryOptions, type InputChange } from './history';
import { ChangeIndex, sameValue } from './historyChanges';
import type { HistoryView, SimLayout, SimView } from './protocol';
import { Replayer, type HistoryState } from './replay';
import type { PlantColumns, TraceColumns } from './scenarioRecording';

/** The machine's names a condition may read (`tank.level > 500`), and their values per recorded scan. */
export interface ConditionPlant {
  /** The machine's spelling of a name it has (`TANK.LEVEL` -> `tank.level`), undefined otherwise. */
  spelling(name: string): string | undefined;
  /** The values of `names` in each scan of [from, to]; undefined for a scan the machine has no record of. */
  values(names: readonly string[], from: number, to: number): (scan: number) => readonly Value[] | undefined;
}
import { recordedBody } from './viewPower';
import { readPinValues, viewBody, viewPou } from './pinValues';

/** Periodic keys wait until the scans since the last key took this many times what saving one takes ... */
const SAVE_SHARE = 20;
/** ... but never longer than this many times keyEvery scans. */
const MAX_KEY_SPACING = 4;

export class HistoryRecorder {
  readonly history: ScanHistory<PlcImage>;
  private readonly probe: PlcProbe;
  private readonly replayer: Replayer;
  private readonly changes: ChangeIndex;
  private readonly index = new Map<string, number>();
  private readonly names: readonly string[];
  /** Outside-change counters (PlcProbe.meters) as of the last recorded scan. */
  private seenInputs = -1;
  private seenState = -1;
  /** Execution time of the scans since the last key, and the least a key took to save (ms; the first ones run before the JIT has optimised saving, and a garbage collection can make any slow). */
  private execSinceKey = 0;
  private saveMs = Infinity;
  /** The input image as of the last recorded scan. */
  private lastInputs: Value[] = [];

  constructor(
    private readonly plc: Plc,
    private readonly layout: SimLayout,
    private readonly program: CompiledProgram,
    private readonly pou: Pou,
    opts: HistoryOptions,
    /** The document the program was compiled from (pins with an operand are read by name). */
    private readonly project?: Project,
  ) {
    this.probe = plc.probe!();
    this.names = layout.variables.map((v) => v.name);
    this.names.forEach((name, i) => this.index.set(name.toUpperCase(), i));
    this.history = new ScanHistory<PlcImage>(opts);
    this.replayer = new Replayer(plc, program, this.history, this.names, (changes) => (this.seenState += changes));
    this.changes = new ChangeIndex(this.history, this.replayer, (i) => this.names[i]!);
  }

  /** A recorder when the PLC offers a probe (the real engine does). */
  static for(plc: Plc, layout: SimLayout, program: unknown, pou: Pou | undefined, opts: HistoryOptions, project?: Project): HistoryRecorder | undefined {
    return plc.probe && pou ? new HistoryRecorder(plc, layout, program as CompiledProgram, pou, opts, project) : undefined;
  }

  /** After a completed scan: `scan` is the session's scan number, `timeMs` the time it started at. */
  record(scan: number, timeMs: number): void {
    const h = this.history;
    const probe = this.probe;
    const meters = probe.meters;
    const exec = (this.execSinceKey += meters[2]!);
    const open = h.open;
    if (
      open === undefined ||
      scan !== open.firstScan + open.count ||
      meters[1] !== this.seenState ||
      ((open.count >= h.keyEvery || exec >= h.keyReplayMs) && (exec >= SAVE_SHARE * this.saveMs || open.count >= MAX_KEY_SPACING * h.keyEvery))
    ) {
      this.key(scan, timeMs);
    } else if (meters[0] !== this.seenInputs) {
      this.seenInputs = meters[0]!;
      h.scan(timeMs, this.plc.timeMs, this.inputChange());
    } else {
      h.scan(timeMs, this.plc.timeMs);
    }
  }

  /** What the input image holds now that it did not at the last recorded scan (undefined: nothing). */
  private inputChange(): InputChange | undefined {
    const image = this.probe.inputImage;
    const last = this.lastInputs;
    let index: number[] | undefined;
    let values: Value[] | undefined;
    for (let i = 0; i < image.length; i++) {
      const v = image[i]!;
      if (sameValue(v, last[i]!)) continue;
      last[i] = v;
      (index ??= []).push(i);
      (values ??= []).push(v);
    }
    return index ? { index, values: values! } : undefined;
  }

  private key(scan: number, timeMs: number): void {
    const t0 = performance.now();
    const image = this.probe.save();
    this.saveMs = Math.min(this.saveMs, performance.now() - t0);
    const cleared = this.history.open !== undefined && scan !== this.history.last! + 1;
    this.history.key(scan, timeMs, this.plc.timeMs, image);
    if (cleared) this.forget();
    this.lastInputs = this.probe.inputImage.slice();
    this.seenInputs = this.probe.meters[0]!;
    this.seenState = this.probe.meters[1]!;
    this.execSinceKey = 0;
  }

  private forget(): void {
    this.replayer.reset();
    this.changes.clear();
  }

  indexOf(name: string): number | undefined {
    return this.index.get(name.trim().toUpperCase());
  }

  /** The state after a recorded scan, rebuilt. */
  seek(scan: number): HistoryState | undefined {
    return this.replayer.state(scan);
  }

  /** The recorded scan as the UI draws it: power bytes by layout and values. */
  /**
   * The recorded scan as a frame of the program's networks, or of the body another `shown` layout
   * monitors (an FB instance, a function: its call that ran in that scan).
   */
  view(scan: number, shown?: SimLayout, current?: SimLayout, text?: TextTarget): HistoryView | undefined {
    // The data lines are sent aligned with the page's layout (the session's current one).
    const layout = current ?? shown ?? this.layout;
    const wordCount = this.probe.power.length;
    // The data lines are read on the PLC that replayed the scan, before the live state is put back.
    let pins: HistoryView['pins'] = [];
    let trace: TextTrace | undefined;
    let replayed = 0;
    const state = this.replayer.state(
      scan,
      (probe, power, plc) => {
        pins = readPinValues(probe, layout, viewBody(this.program, layout, (n) => power[wordCount + n] === 1), this.project && viewPou(this.project, layout));
        trace = text && plc.textTrace(text);
        replayed = plc.scanCount;
      },
      text,
    );
    if (!state) return undefined;
    const words = this.probe.power.length;
    const executed = Uint8Array.from(state.power.subarray(words));
    const networks = this.probe.decode(state.power.subarray(0, words), executed);
    const packed = shown
      ? packNetworks(recordedBody(this.program, shown, networks), shown)
      : packNetworks(networks, this.layout);
    // The replaying PLC counts its scans from its own start: the trace is numbered like the view.
    const shownText = trace && { ...trace, scan: scan - (replayed - trace.scan), stale: trace.scan !== replayed };
    return { scan, timeMs: state.timeMs, ...packed, values: state.values, pins, ...(shownText ? { text: shownText } : {}) };
  }

  /** The recorded scan as "Why?" reads it. */
  scanView(scan: number, forced?: ReadonlySet<string>): ScanView | undefined {
    const state = this.replayer.state(scan);
    if (!state) return undefined;
    const { program } = this;
    const words = this.probe.words;
    const wordCount = this.probe.power.length;
    const ran = (n: number) => state.power[wordCount + n] === 1;
    return {
      scan,
      timeMs: state.timeMs,
      value: (name) => {
        const i = this.indexOf(name);
        return i === undefined ? undefined : state.values[i];
      },
      executed: ran,
      net: (n, net) => netOn(program, words, state.power, ran(n), n, net),
      changedAt: (name) => {
        const i = this.indexOf(name);
        return i === undefined ? undefined : this.changes.lastChange(i, scan);
      },
      ...(forced ? { forced } : {}),
    };
  }

  /**
   * "Why?" at a recorded scan. With the `project`, explanations follow values through every body the
   * program runs (FB instances by path); with a `shown` body (an FB instance, a function, another
   * program instance), an element target is one of that body's networks, in its call of that scan.
   */
  explain(
    scan: number,
    target: ExplainTarget,
    forced?: ReadonlySet<string>,
    whole?: { readonly project: Project; readonly shown?: SimView },
  ): Explanation | undefined {
    const view = this.scanView(scan, forced);
    if (!view) return undefined;
    const pou = whole ? flattenedPou(this.program, whole.project, this.pou) : this.pou;
    if (whole?.shown && target.kind === 'element') {
      const network = flatNetwork(this.program, whole.shown, target.network, view.executed);
      if (network === undefined)
        return { scan, target, title: 'Nothing to explain', lines: [`${whole.shown.instance ?? whole.shown.pou} is not called by the program, so its networks did not run.`], marks: [], links: [] };
      return { ...explain(this.program, pou, view, { ...target, network }), target };
    }
    return explain(this.program, pou, view, target);
  }

  /** Next/previous change of a name, or the next/previous scan where a condition holds (not `from` itself). */
  findChange(name: string, from: number, direction: 1 | -1): number | undefined {
    const i = this.indexOf(name);
    if (i === undefined) throw new Error(`"${name}" is not recorded`);
    if (direction === 1) return this.changes.nextChange(i, from);
    const at = this.changes.lastChange(i, from);
    if (at === undefined) return undefined;
    return at < from ? at : this.changes.lastChange(i, from - 1);
  }

  findCondition(expression: string, from: number, direction: 1 | -1, plant?: ConditionPlant): number | undefined {
    // The condition's names in the order it reads them: the program's recorded ones (`names`, their
    // values walked from the history) and the machine's (`tank.level`, worked out from its history).
    const names: string[] = [];
    const machine: string[] = [];
    const slots: number[] = [];
    const test = compileCondition(expression, (n) => {
      const i = this.indexOf(n);
      const key = i !== undefined ? this.names[i]! : plant?.spelling(n);
      if (key === undefined) return undefined;
      const list = i !== undefined ? names : machine;
      let at = list.indexOf(key);
      if (at < 0) at = list.push(key) - 1;
      const slot = i !== undefined ? at : -1 - at;
      const known = slots.indexOf(slot);
      return known >= 0 ? known : slots.push(slot) - 1;
    });
    const first = this.history.first;
    if (first === undefined) return undefined;
    const last = this.history.last!;
    const machineAt = plant && machine.length ? plant.values(machine, first, last) : undefined;
    const read = new Array<Value>(slots.length);
    const holds = (values: readonly Value[], scan: number) => {
      if (!machineAt) return test(values);
      const m = machineAt(scan);
      if (!m) return false;
      for (let k = 0; k < slots.length; k++) read[k] = slots[k]! >= 0 ? values[slots[k]!]! : m[-1 - slots[k]!]!;
      return test(read);
    };
    const start = from + direction;
    if (direction === 1) return start > last ? undefined : this.replayer.walk(Math.max(start, first), last, names, holds);
    // Backwards: segment by segment from the newest, the last scan where it holds in each.
    for (let upTo = Math.min(start, last); upTo >= first; ) {
      const seg = this.history.segmentOf(upTo)!;
      const segFrom = Math.max(seg.firstScan, first);
      let found: number | undefined;
      this.replayer.walk(segFrom, upTo, names, (values, scan) => {
        if (holds(values, scan)) found = scan;
        return false;
      });
      if (found !== undefined) return found;
      upTo = segFrom - 1;
    }
    return undefined;
  }

  /** The recorded scans within [from, to], or undefined when none is recorded. */
  recordedRange(from?: number, to?: number): [number, number] | undefined {
    const first = this.history.first;
    if (first === undefined) return undefined;
    return [Math.max(first, from ?? first), Math.min(this.history.last!, to ?? this.history.last!)];
  }

  private types(names: readonly string[]): { index: number; type: ElementaryType; name: string }[] {
    return names.map((name) => {
      const index = this.indexOf(name);
      if (index === undefined) throw new Error(`"${name}" is not recorded`);
      const v = this.layout.variables[index]!;
      return { index, type: v.type as ElementaryType, name: v.name };
    });
  }

  /** Replays the range, calling `visit` with the values of `cols` after each scan (the array is reused). */
  private each(cols: readonly { name: string }[], range: [number, number], visit: (values: readonly Value[], scan: number) => void): void {
    this.replayer.walk(
      range[0],
      range[1],
      cols.map((c) => c.name),
      (values, scan) => {
        visit(values, scan);
        return false;
      },
    );
  }

  /** The recorded range as a trace in the CLI's format: scan,time_ms,<names...> (BOOL 0/1, TIME in ms). */
  traceCsv(names: readonly string[], from?: number, to?: number, plant?: TraceColumns): string {
    const cols = this.types(names);
    const lines = [csvRow(['scan', 'time_ms', ...cols.map((c) => c.name), ...(plant?.names ?? [])])];
    const range = this.recordedRange(from, to);
    if (range)
      this.each(cols, range, (values, scan) => {
        lines.push(csvRow([String(scan), String(this.history.timeOf(scan)), ...cols.map((c, j) => csvValue(c.type, values[j]!)), ...(plant?.cells(scan) ?? [])]));
      });
    return `${lines.join('\n')}\n`;
  }

  /**
   * The recorded range as a test scenario: the inputs where they changed (scan 1 = the range's
   * first scan, every input set there), and the outputs expected at those scans and wherever they changed.
   */
    scenarioCsv(inputs: readonly string[], outputs: readonly string[], cycleMs: number, from?: number, to?: number, plant?: PlantColumns): string {
    const ins = this.types(inputs);
    const outs = this.types(outputs);
    const range = this.recordedRange(from, to);
    const head = [
      `# Recorded from scans ${range ? `${range[0]} to ${range[1]}` : '(none)'} of a simulation`,
      `# cycle: ${cycleMs}ms`,
      ...(plant ? [`# plant: ${plant.id}`] : []),
    ];
    // The machine's operator controls and faults (pressed / set: 1, else 0) after the inputs.
    const extra = plant?.names ?? [];
    const lines = [csvRow(['scan', ...ins.map((c) => c.name), ...extra, ...outs.map((c) => `expect ${c.name}`)])];
    if (range) {
      const n = ins.length;
      let prev: Value[] | undefined;
      let prevExtra: readonly boolean[] | undefined;
      this.each([...ins, ...outs], range, (values, scan) => {
        const k = scan - range[0] + 1;
        const now = plant?.at(scan) ?? [];
        const changedIn = ins.map((_, j) => !prev || !sameValue(prev[j]!, values[j]!));
        const changedExtra = now.map((v, j) => !prevExtra || prevExtra[j] !== v);
        const changedOut = outs.some((_, j) => !prev || !sameValue(prev[n + j]!, values[n + j]!));
        if (changedIn.some(Boolean) || changedExtra.some(Boolean) || changedOut || scan === range[1])
          lines.push(
            csvRow([
              String(k),
              ...ins.map((c, j) => (changedIn[j] ? csvValue(c.type, values[j]!) : '')),
              ...now.map((v, j) => (changedExtra[j] ? (v ? '1' : '0') : '')),
              ...outs.map((c, j) => csvValue(c.type, values[n + j]!)),
            ]),
          );
        prev = values.slice();
        prevExtra = now;
      });
    }
    return `${[...head, ...lines].join('\n')}\n`;
  }
}
