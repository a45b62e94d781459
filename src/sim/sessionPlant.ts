// The machine the simulation runs against (issue 26): one PlantLoop in the worker, beside the
// program. It is stepped after every completed scan (the runner's scanCompleted: outputs written,
// next inputs not yet read) by the scan's PLC time, reset with a cold restart, re-bound to each
// program installed (an online change keeps the machine as it is), and shown in frames.
import type { Plc } from '../engine/api';
import { requirePlant } from '../plant/machines';
import { PlantLoop, type PlantEvent, type PlantMap, type PlantSnapshot } from '../plant/loop';
import type { PlantPoint } from '../plant/types';
import type { Value } from '../model/iecTypes';
import { plantNames, plantSpelling, type PlantName } from '../plant/values';
import type { PlantWhyContext } from './plantWhy';
import type { RecordedPlant } from './scenarioRecording';

/** Consequences a frame carries (the newest); the panel lists them. */
const FRAME_EVENTS = 50;

export interface PlantFrame {
  readonly id: string;
  readonly points: readonly PlantPoint[];
  readonly now: PlantSnapshot;
  /** The newest consequences, oldest first, and how many there were since the cold start. */
  readonly events: readonly PlantEvent[];
  readonly eventCount: number;
  /** The scan after which this machine (with this wiring) began driving the program (0: from the cold start). */
  readonly since: number;
}

export class SessionPlant {
  private loop: PlantLoop | undefined;
  /**
   * Push buttons pressed since the last scan while running, and those of them already let go: a
   * click shorter than the scan cycle (a quick click at a slow cycle) stays pressed until a scan
   * has read it, then springs back, so a click on the drawing is never lost. The program sees it
   * for one scan, the machine for one step, as a press held that long. (Stopped or paused, no
   * scan is coming: a click is let go when it is.)
   */
  private unread = new Set<string>();
  private letGo = new Set<string>();
  /**
   * The scan after which this loop began driving the program (0: from the cold start): a machine
   * chosen or rewired while the program was at scan 240 drives the inputs scan 241 reads. Scans up
   * to it were not this machine's (another machine, another wiring, or none).
   */
  private since = 0;

  get active(): boolean {
    return this.loop !== undefined;
  }

  /** Attaches the machine (`null`: none). A new machine or map starts from its initial state. */
  configure(config: { readonly id: string; readonly map?: PlantMap } | null, plc: Plc | undefined): void {
    if (!config) {
      this.loop?.release();
      this.loop = undefined;
      this.unread.clear();
      this.letGo.clear();
      return;
    }
    let loop: PlantLoop;
    try {
      loop = new PlantLoop(requirePlant(config.id), config.map ?? {});
    } catch (e) {
      // A machine or wiring refused (a map with two points on one address, a bad address): the
      // machine attached before is taken away all the same, its inputs falling to FALSE / 0,
      // rather than left driving the program as if it had been chosen.
      this.loop?.release();
      this.loop = undefined;
      throw e;
    }
    // The same machine with the same wiring keeps its loop (state, faults, operator controls, history).
    if (
      this.loop &&
      this.loop.model.id === loop.model.id &&
      JSON.stringify(this.loop.points) === JSON.stringify(loop.points)
    )
      return;
    this.loop?.release();
    // The same machine rewired: it goes on as it was (a terminal moved does not refill the tank),
    // a click not yet read included; another machine has no such press.
    if (this.loop?.model.id === loop.model.id) loop.continueFrom(this.loop);
    else {
      this.unread.clear();
      this.letGo.clear();
    }
    this.loop = loop;
    this.since = plc?.scanCount ?? 0;
    if (plc) loop.bind(plc);
  }

  /** A program was installed: afresh (the machine starts over) or by an online change (it goes on). */
  install(plc: Plc, fresh: boolean): void {
    if (!this.loop) return;
    if (fresh) {
      this.loop.reset();
      this.since = 0;
    }
    this.loop.bind(plc);
  }

  coldRestart(plc: Plc | undefined): void {
    if (!this.loop) return;
    this.releaseUnread();
    this.loop.reset();
    this.since = 0;
    if (plc) this.loop.bind(plc);
  }

  afterScan(scan: number, startTimeMs: number, cycleMs: number): void {
    this.loop?.afterScan(scan, startTimeMs, cycleMs);
    // Presses this scan read: those let go spring back now.
    if (this.unread.size > 0) this.releaseUnread();
  }

  private releaseUnread(): void {
    this.unread.clear();
    for (const name of this.letGo) this.loop?.setOperator(name, false);
    this.letGo.clear();
  }

  /** An operator control held (TRUE) or let go; `running`: scans are coming (a click is held until one reads it). */
  setOperator(name: string, value: boolean, running = false): void {
    const loop = this.require();
    const button = running
      ? loop.points.find(
          (p) => p.kind === 'operator' && p.control !== 'switch' && p.name.toUpperCase() === name.toUpperCase(),
        )
      : undefined;
    // Let go before any scan read the press: held until the next scan has.
    if (button && !value && this.unread.has(button.name)) {
      this.letGo.add(button.name);
      return;
    }
    loop.setOperator(name, value);
    if (button && value) {
      this.unread.add(button.name);
      this.letGo.delete(button.name);
    }
  }

  setFault(id: string, active: boolean): void {
    this.require().setFault(id, active);
  }

  at(scan: number): PlantSnapshot | undefined {
    return this.loop?.at(scan);
  }

  /** The machine's readable names (`tank.level`, `tank.Pump`) for the watch, the trend and "Why?"; none without a machine. */
  names(): PlantName[] {
    return this.loop ? plantNames(this.loop.model) : [];
  }

  /** The machine's spelling of one of its names (`TANK.LEVEL` -> `tank.level`), or undefined. */
  spelling(name: string): string | undefined {
    return this.loop && plantSpelling(this.loop.model, name);
  }

  /** `tank.level` now (after the last step). */
  read(name: string): Value {
    return this.require().read(name);
  }

  /** What "Why?" needs of the machine, or undefined without one. */
  whyContext(): PlantWhyContext | undefined {
    const loop = this.loop;
    return loop && { model: loop.model, points: loop.points, at: (scan) => loop.at(scan), since: this.since };
  }

  /** What recording the history as a scenario needs of the machine, or undefined without one. */
  recording(): RecordedPlant | undefined {
    const loop = this.loop;
    return loop && { id: loop.model.id, model: loop.model, points: loop.points, controlsAt: (scan) => loop.controlsAt(scan), walk: (from, to, fn) => loop.walk(from, to, fn) };
  }

  /** For scenario replays in the simulator: the machine's loop, started over. */
  forScenario(id: string): PlantLoop {
    if (this.loop?.model.id !== id) this.configure({ id }, undefined);
    this.loop!.reset();
    this.since = 0;
    return this.loop!;
  }

  frame(): PlantFrame | undefined {
    const loop = this.loop;
    if (!loop) return undefined;
    const all = loop.consequences();
    return {
      id: loop.model.id,
      points: loop.points,
      now: loop.snapshot(),
      events: all.slice(-FRAME_EVENTS),
      eventCount: all.length,
      since: this.since,
    };
  }

  private require(): PlantLoop {
    if (!this.loop) throw new Error('no machine is attached: choose one in the Plant panel');
    return this.loop;
  }
}
