// Records every completed scan of the running PLC into a ScanHistory (values of every layout name,
// FB pins included, and the packed power words with each network's executed flag), and reads a
// recorded scan back as a frame for the UI, a ScanView for "Why?", a trace CSV or a scenario.
import type { Plc, PlcProbe } from '../engine/api';
import { explain, netOn, type Explanation, type ExplainTarget, type ScanView } from '../engine/explain';
import type { CompiledProgram } from '../engine/plc';
import { csvValue } from '../engine/values/literals';
import type { ElementaryType, Value } from '../model/iecTypes';
import type { Pou } from '../model/project';
import { compileCondition } from './condition';
import { csvRow } from './csv';
import { packNetworks } from './frames';
import { ScanHistory, type HistoryOptions } from './history';
import type { HistoryView, SimLayout } from './protocol';

export class HistoryRecorder {
  readonly history: ScanHistory;
  private readonly probe: PlcProbe;
  private readonly sample: (out: Value[]) => void;
  private readonly values: Value[];
  private readonly wordCount: number;
  private readonly scratch: Int32Array;
  private readonly index = new Map<string, number>();

  constructor(
    private readonly plc: Plc,
    private readonly layout: SimLayout,
    private readonly program: CompiledProgram,
    private readonly pou: Pou,
    opts: HistoryOptions,
  ) {
    this.probe = plc.probe!();
    this.sample = this.probe.sampler(layout.variables.map((v) => v.name));
    this.values = new Array<Value>(layout.variables.length).fill(false);
    layout.variables.forEach((v, i) => this.index.set(v.name.toUpperCase(), i));
    this.wordCount = this.probe.power.length;
    const networks = this.probe.ranIn.length;
    this.scratch = new Int32Array(this.wordCount + networks);
    this.history = new ScanHistory(layout.variables.length, this.scratch.length, opts);
  }

  /** A recorder when the PLC offers a probe (the real engine does). */
  static for(plc: Plc, layout: SimLayout, program: unknown, pou: Pou | undefined, opts: HistoryOptions): HistoryRecorder | undefined {
    return plc.probe && pou ? new HistoryRecorder(plc, layout, program as CompiledProgram, pou, opts) : undefined;
  }

  /** After a completed scan: `scan` is the session's scan number. */
  record(scan: number, timeMs: number): void {
    const { scratch, probe, wordCount } = this;
    scratch.set(probe.power);
    const own = this.plc.scanCount;
    const ranIn = probe.ranIn;
    for (let n = 0; n < ranIn.length; n++) scratch[wordCount + n] = ranIn[n] === own ? 1 : 0;
    this.sample(this.values);
    this.history.record(scan, timeMs, this.values, scratch);
  }

  indexOf(name: string): number | undefined {
    return this.index.get(name.trim().toUpperCase());
  }

  /** The recorded scan as the UI draws it: power bytes by layout and values. */
  view(scan: number): HistoryView | undefined {
    const state = this.history.seek(scan);
    if (!state) return undefined;
    const executed = Uint8Array.from(state.power.subarray(this.wordCount));
    const networks = this.probe.decode(state.power.subarray(0, this.wordCount), executed);
    const packed = packNetworks(networks, this.layout);
    return { scan, timeMs: state.timeMs, ...packed, values: state.values };
  }

  /** The recorded scan as "Why?" reads it. */
  scanView(scan: number, forced?: ReadonlySet<string>): ScanView | undefined {
    const state = this.history.seek(scan);
    if (!state) return undefined;
    const { program, wordCount } = this;
    const words = this.probe.words;
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
        return i === undefined ? undefined : this.history.lastChange(i, scan);
      },
      ...(forced ? { forced } : {}),
    };
  }

  explain(scan: number, target: ExplainTarget, forced?: ReadonlySet<string>): Explanation | undefined {
    const view = this.scanView(scan, forced);
    return view ? explain(this.program, this.pou, view, target) : undefined;
  }

  /** Next/previous change of a name, or the next/previous scan where a condition holds (not `from` itself). */
  findChange(name: string, from: number, direction: 1 | -1): number | undefined {
    const i = this.indexOf(name);
    if (i === undefined) throw new Error(`"${name}" is not recorded`);
    return this.history.nextChange(i, from, direction);
  }

  findCondition(expression: string, from: number, direction: 1 | -1): number | undefined {
    const test = compileCondition(expression, (n) => this.indexOf(n));
    return this.history.find(from + direction, direction, (values) => test(values));
  }

  private range(from?: number, to?: number): [number, number] | undefined {
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

  /** The recorded range as a trace in the CLI's format: scan,time_ms,<names...> (BOOL 0/1, TIME in ms). */
  traceCsv(names: readonly string[], from?: number, to?: number): string {
    const cols = this.types(names);
    const lines = [csvRow(['scan', 'time_ms', ...cols.map((c) => c.name)])];
    const range = this.range(from, to);
    if (range)
      this.history.find(range[0], 1, (values, scan) => {
        if (scan > range[1]) return true;
        lines.push(csvRow([String(scan), String(this.history.timeOf(scan)), ...cols.map((c) => csvValue(c.type, values[c.index]!))]));
        return false;
      });
    return `${lines.join('\n')}\n`;
  }

  /**
   * The recorded range as a test scenario: the inputs where they changed (scan 1 = the range's
   * first scan, every input set there), and the outputs expected at those scans and wherever they changed.
   */
  scenarioCsv(inputs: readonly string[], outputs: readonly string[], cycleMs: number, from?: number, to?: number): string {
    const ins = this.types(inputs);
    const outs = this.types(outputs);
    const range = this.range(from, to);
    const head = [`# Recorded from scans ${range ? `${range[0]} to ${range[1]}` : '(none)'} of a simulation`, `# cycle: ${cycleMs}ms`];
    const lines = [csvRow(['scan', ...ins.map((c) => c.name), ...outs.map((c) => `expect ${c.name}`)])];
    if (range) {
      let prev: Value[] | undefined;
      this.history.find(range[0], 1, (values, scan) => {
        if (scan > range[1]) return true;
        const k = scan - range[0] + 1;
        const changedIn = ins.map((c) => !prev || prev[c.index] !== values[c.index]);
        const changedOut = outs.some((c) => !prev || prev[c.index] !== values[c.index]);
        if (changedIn.some(Boolean) || changedOut || scan === range[1])
          lines.push(csvRow([String(k), ...ins.map((c, j) => (changedIn[j] ? csvValue(c.type, values[c.index]!) : '')), ...outs.map((c) => csvValue(c.type, values[c.index]!))]));
        prev = values.slice();
        return false;
      });
    }
    return `${[...head, ...lines].join('\n')}\n`;
  }
}
