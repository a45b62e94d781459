// The PLC as the rest of the app drives it (the Plc interface of ../api): scan and step counts,
// reading and writing variables, forcing (writes redirected to a spare slot, no code regenerated),
// the input and output images at locations, online change (state export/import), the probe used by
// scan history and replay, and power snapshots of a POU or an instance. The scan cycle itself
// (LD-SEMANTICS.md section 7: input image -> networks -> output image, the clock, tasks at several
// rates or on events, watchdog, stepping, restarts) is its base class, ScanCycle in scanCycle.ts.
import type { Value } from '../../model/iecTypes';
import type {
  Fault,
  InstanceInfo,
  NetworkPower,
  Plc,
  PlcProbe,
  PinLines,
  PlcState,
  PowerSnapshot,
  ScanReport,
  IoImage,
  IoPoint,
  SnapshotOptions,
  StateItem,
  StateTransfer,
} from '../api';
import type { BodyInfo } from '../compile/flatten';
import { slotKey } from '../compile/emitter';
import { pinLines } from '../compile/pinLines';
import { networkPower, type PowerTrace } from './snapshot';
import { programOf } from '../compile/taskSchedule';
import type { Access, VarSymbol } from '../compile/symbols';
import { coerce } from './memory';
import { exportMemory, importMemory, stateItemsOf } from './instanceState';
import { imageBytes, restoreMemory, saveMemory, type MachineImage } from './machineImage';
import { ScanCycle, type TextRecord } from './scanCycle';

type Image = MachineImage<Value, readonly [VarSymbol, Value]>;

export class ScanPlc extends ScanCycle implements Plc {
  get scanCount(): number {
    return this.count;
  }
  get timeMs(): number {
    return this.time;
  }
  get fault(): Fault | undefined {
    return this.currentFault;
  }
  get nextNetwork(): number {
    return this.cursor >= 0 ? this.cursor : -1;
  }

  private report(): ScanReport {
    return {
      scan: this.count,
      timeMs: this.time,
      execMs: this.lastExecMs,
      ...(this.currentFault ? { fault: this.currentFault } : {}),
    };
  }

  scan(): ScanReport {
    this.runScans(1);
    return this.report();
  }

  scans(n: number): ScanReport {
    this.runScans(n);
    return this.report();
  }

  runUntil(cond: (plc: Plc) => boolean, maxScans: number): boolean {
    for (let k = 0; k < maxScans && !this.currentFault; k++) {
      this.runScans(1);
      if (!this.currentFault && cond(this)) return true;
    }
    return false;
  }

  instances(): readonly InstanceInfo[] {
    return this.program.instances;
  }

  clearFault(): void {
    this.meters[1]!++;
    this.currentFault = undefined;
    this.cursor = -1;
    this.stepper = undefined;
    this.frames = [];
  }

  // ---- variables ----

  /**
   * Names resolved so far: a program's symbols never change after its compile, and the simulator
   * reads the same names every frame (every shown variable, 40 times a second).
   */
  private readonly resolved = new Map<string, Access>();

  private access(name: string): Access {
    const known = this.resolved.get(name);
    if (known) return known;
    const res = this.program.symbols.resolve(name, { literals: false, implicitLocations: false });
    if (!res.ok) throw new Error(`${name}: ${res.message}`);
    this.resolved.set(name, res.access);
    return res.access;
  }

  read(name: string): Value {
    return this.mem.read(this.access(name));
  }

  write(name: string, value: Value): void {
    const a = this.access(name);
    const v = coerce(a.type, value, `"${name}"`);
    const input = a.kind === 'var' && a.v.location?.area === 'I';
    this.meters[input && this.cursor === -1 ? 0 : 1]!++;
    if (input) {
      this.inputImage[this.inputs.indexOf(a.v)] = v;
      this.inputWrites[0]!++;
      return;
    }
    if ((a.kind === 'var' || a.kind === 'bit') && this.forces.has(a.v)) return; // a forced value wins
    this.mem.write(a, v);
  }

  private forceTarget(name: string): VarSymbol {
    const a = this.access(name);
    if (a.kind !== 'var') throw new Error(`${name}: only variables can be forced (not FB pins or bits)`);
    return a.v;
  }

  force(name: string, value: Value): void {
    const v = this.forceTarget(name);
    const val = coerce(v.type, value, `"${name}"`);
    const fresh = !this.forces.has(v);
    this.meters[1]!++;
    this.forces.set(v, val);
    this.mem.store(v, val);
    if (fresh) this.redirectWriters(v, true);
  }

  unforce(name: string): void {
    const v = this.forceTarget(name);
    this.meters[1]!++;
    if (this.forces.delete(v)) this.redirectWriters(v, false);
  }

  unforceAll(): void {
    this.meters[1]!++;
    const vars = [...this.forces.keys()];
    this.forces.clear();
    for (const v of vars) this.redirectWriters(v, false);
  }

  forced(): ReadonlyMap<string, Value> {
    return new Map([...this.forces].map(([v, val]) => [v.name, val]));
  }

  /**
   * Points the program's writes to a variable at a spare slot (Memory.sink) while it is forced,
   * so they do not stick, and back at the variable when it is unforced; no code is regenerated.
   */
  private redirectWriters(v: VarSymbol, forced: boolean): void {
    const key = slotKey(v.store, v.slot);
    if (forced) this.forcedSlots.add(key);
    else this.forcedSlots.delete(key);
    const target = forced ? this.mem.sink[v.store] : v.slot;
    for (const at of this.plan.writes.get(key) ?? []) this.plan.P[at] = target;
    for (const at of this.stepPlan?.writes.get(key) ?? []) this.stepPlan!.P[at] = target;
    this.tiering.invalidate(this.plan.writers.get(key) ?? []);
  }

  setInputs(values: Readonly<Record<string, Value>>): void {
    this.meters[this.cursor === -1 ? 0 : 1]!++;
    for (const [loc, value] of Object.entries(values)) {
      const v = this.program.symbols.atLocation(loc, false);
      const index = v ? this.inputs.indexOf(v) : -1;
      if (!v || index < 0) throw new Error(`${loc}: no input variable is declared at this location`);
      this.inputImage[index] = coerce(v.type, value, loc);
      this.inputWrites[0]!++;
    }
  }

  ioPoint(location: string): IoPoint | undefined {
    const v = this.program.symbols.atLocation(location, false);
    if (!v) return undefined;
    const input = this.inputs.indexOf(v);
    if (input >= 0) {
      const image = this.inputImage;
      const meters = this.meters;
      const writes = this.inputWrites;
      return {
        read: () => image[input]!,
        write: (value) => {
          meters[this.cursor === -1 ? 0 : 1]!++;
          image[input] = typeof value === 'boolean' && v.type === 'BOOL' ? value : coerce(v.type, value, location);
          writes[0]!++;
        },
      };
    }
    const output = this.outputsVars.indexOf(v);
    if (output < 0) return undefined;
    const image = this.outputImage;
    return {
      read: () => image[output]!,
      write: () => {
        throw new Error(`${location} is an output: the program writes it`);
      },
    };
  }

  private image: IoImage | undefined;

  ioImage(): IoImage {
    if (this.image) return this.image;
    const inputs = this.inputs;
    const image = this.inputImage;
    const meters = this.meters;
    const writes = this.inputWrites;
    const atLocation = (location: string) => this.program.symbols.atLocation(location, false);
    this.image = {
      inputs: image,
      outputs: this.outputImage,
      inputWrites: writes,
      input: (location) => {
        const v = atLocation(location);
        return v ? inputs.indexOf(v) : -1;
      },
      output: (location) => {
        const v = atLocation(location);
        return v ? this.outputsVars.indexOf(v) : -1;
      },
      // As ioPoint's write: counted as an input written at a boundary (or a change from outside mid-scan).
      write: (index, value) => {
        const v = inputs[index]!;
        meters[this.cursor === -1 ? 0 : 1]!++;
        image[index] = typeof value === 'boolean' && v.type === 'BOOL' ? value : coerce(v.type, value, v.locationText ?? v.name);
        writes[0]!++;
      },
    };
    return this.image;
  }

  outputs(): Record<string, Value> {
    const out: Record<string, Value> = {};
    this.outputsVars.forEach((v, i) => (out[v.locationText!] = this.outputImage[i]!));
    return out;
  }

  variableNames(): string[] {
    const names = this.program.symbols.vars.filter((v) => !v.hidden).map((v) => v.name);
    for (const fb of this.program.symbols.fbs)
      for (const pin of this.mem.fbs[fb.index]!.pins()) names.push(`${fb.name}.${pin}`);
    return names;
  }

  values(): Record<string, Value> {
    const out: Record<string, Value> = {};
    for (const v of this.program.symbols.vars) if (!v.hidden) out[v.name] = this.mem.load(v);
    return out;
  }

  // ---- online change ----

  /** The time the next scan would start at, on this PLC's clock. */
  private nextScanTime(): number {
    return this.opts.clock ? this.opts.clock.now() - this.clockOrigin : this.count * this.cycleMs;
  }

  stateItems(): readonly StateItem[] {
    return stateItemsOf(this.program);
  }

  exportState(): PlcState {
    return exportMemory(this.program, this.mem, this.nextScanTime());
  }

  importState(state: PlcState): StateTransfer {
    this.meters[1]!++;
    return importMemory(this.program, this.mem, state, this.nextScanTime());
  }

  /** Data lines per body range (PlcProbe.pinLines), made on first use. */
  private readonly lineCache = new Map<string, PinLines>();

  private pinLines(first: number, end: number): PinLines {
    const key = `${first}:${end}`;
    const hit = this.lineCache.get(key);
    if (hit) return hit;
    const mem = this.mem;
    const found = pinLines(this.program, first, end);
    const readers = found.map((l): (() => Value) => {
      const src = l.src;
      if (src.from === 'access') {
        const a = src.access;
        return () => mem.read(a);
      }
      const slot = { store: src.store, slot: src.slot } as VarSymbol;
      return () => mem.load(slot);
    });
    const lines: PinLines = {
      lines: found.map(({ network, element, pin, side, type }) => ({ network, element, pin, side, type })),
      read: (out) => {
        for (let i = 0; i < readers.length; i++) out[i] = readers[i]!();
      },
    };
    this.lineCache.set(key, lines);
    return lines;
  }

  probe(): PlcProbe {
    const { program, mem, words } = this;
    return {
      reader: (name) => {
        const a = this.access(name);
        return () => mem.read(a);
      },
      sampler: (names) => {
        // Straight-line reads (like the generated scan code): a variable from its store, a standard
        // FB pin from its field; anything else through Memory.read.
        const accesses = names.map((name) => this.access(name));
        const body = accesses.map((a, i) => {
          if (a.kind === 'var') return a.v.store === 'b' ? `o[${i}] = b[${a.v.slot}] === 1;` : `o[${i}] = ${a.v.store}[${a.v.slot}];`;
          if (a.kind === 'pin' && /^[A-Z_][A-Z0-9_]*$/i.test(a.pin) && a.pin in mem.fbs[a.fb.index]!) return `o[${i}] = f[${a.fb.index}].${a.pin};`;
          return `o[${i}] = m.read(a[${i}]);`;
        });
        const make = new Function('b', 'n', 'g', 'f', 'm', 'a', `return (o) => {\n${body.join('\n')}\n};`) as (...args: unknown[]) => (out: Value[]) => void;
        return make(mem.b, mem.n, mem.g, mem.fbs, mem, accesses);
      },
      power: this.power,
      ranIn: this.ranIn,
      words,
      decode: (power: Int32Array, executed: Uint8Array): NetworkPower[] => {
        const ranIn = Int32Array.from(executed, (e) => (e ? 1 : -1));
        return networkPower(program, { scan: 1, power, words, ranIn });
      },
      meters: this.meters,
      inputImage: this.inputImage,
      pinLines: (first, end) => this.pinLines(first, end),
      save: () => this.saveImage(),
      restore: (image) => this.restoreImage(image as Image),
      replay: (timeMs, inputs) => {
        if (inputs) {
          for (let i = 0; i < this.inputImage.length; i++) this.inputImage[i] = inputs[i]!;
          this.inputWrites[0]!++;
        }
        this.replayAt = timeMs;
        try {
          this.runScans(1);
        } finally {
          this.replayAt = undefined;
        }
        return this.currentFault;
      },
    };
  }

  /** The complete state at a scan boundary (PlcProbe.save). */
  private saveImage(): Image {
    const mem = saveMemory(this.mem);
    const extra = this.power.length / 2 + this.ranIn.length / 2 + this.inputImage.length + this.outputImage.length + this.forces.size * 2;
    return {
      scan: this.count,
      timeMs: this.time,
      bytes: imageBytes(mem, extra),
      mem,
      power: this.power.slice(),
      ranIn: this.ranIn.slice(),
      inputs: this.inputImage.slice(),
      outputs: this.outputImage.slice(),
      forces: [...this.forces],
      traces: new Map(this.traces),
    };
  }

  /** Takes back a saved state (PlcProbe.restore): memory, power, input and output images, forces, scan count and time. */
  private restoreImage(image: Image): void {
    this.clearFault();
    restoreMemory(this.mem, image.mem);
    this.power.set(image.power);
    this.ranIn.set(image.ranIn);
    image.inputs.forEach((v, i) => (this.inputImage[i] = v));
    this.inputWrites[0]!++;
    image.outputs.forEach((v, i) => (this.outputImage[i] = v));
    const forced = new Map(image.forces);
    for (const v of [...this.forces.keys()]) if (!forced.has(v)) {
      this.forces.delete(v);
      this.redirectWriters(v, false);
    }
    for (const [v, value] of forced) {
      const fresh = !this.forces.has(v);
      this.forces.set(v, value);
      if (fresh) this.redirectWriters(v, true);
    }
    this.count = image.scan;
    this.time = image.timeMs;
    if (image.traces) {
      this.traces.clear();
      for (const [b, t] of image.traces) this.traces.set(b, t as TextRecord);
    }
  }

  snapshot(opts: SnapshotOptions = {}): PowerSnapshot {
    const body = opts.instance === undefined ? this.program.bodies[0] : this.bodyOfInstance(opts.instance);
    if (!body) throw new Error(`${opts.instance}: no FB or program instance of this name is called`);
    const trace: PowerTrace = {
      scan: this.shownScan(body),
      power: this.power,
      words: this.words,
      ranIn: this.ranIn,
    };
    return {
      scan: this.count,
      timeMs: this.time,
      pou: body?.pou ?? this.pou,
      ...(opts.instance !== undefined && body.instance ? { instance: body.instance } : {}),
      networks: networkPower(this.program, trace, body?.first ?? 0, body?.end ?? 0),
    };
  }

  /**
   * The scan whose power flow a body shows: this one, or, when its program's task was not due at
   * this tick, the program's last run (its power is unchanged since: the view does not blink).
   */
  private shownScan(body: BodyInfo): number {
    const rates = this.rates;
    if (!rates) return this.count;
    const root = programOf(this.program.bodies, body);
    const p = this.program.bodies.indexOf(root);
    if (p < 0 || p >= rates.due.length || rates.due[p] === 1 || root.end <= root.first) return this.count;
    // Never run yet (an event task not triggered since the restart): scan 0, which no network ran in.
    return Math.max(0, this.ranIn[root.first]!);
  }

  /** The body of an instance's call that ran last in the scan (the first call if none ran). */
  private bodyOfInstance(path: string): BodyInfo | undefined {
    const key = path.trim().toUpperCase();
    let best: BodyInfo | undefined;
    for (const b of this.program.bodies) {
      if (b.instance?.toUpperCase() !== key) continue;
      if (!best || (b.end > b.first && (this.ranIn[b.first] ?? -1) > (this.ranIn[best.first] ?? -1))) best = b;
    }
    return best;
  }
}
