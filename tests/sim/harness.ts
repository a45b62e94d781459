// Drives a SimSession as the worker would, recording what it posts.
import type { Value } from '../../src/model/iecTypes';
import { realEngine } from '../../src/sim/engineAdapter';
import type { HostMessage, SimFrame, SimLayout, WorkerMessage } from '../../src/sim/protocol';
import { SimSession } from '../../src/sim/session';
import type { SimEngine } from '../../src/sim/simEngine';
import { ManualScheduler } from './manualScheduler';

export class SimHarness {
  readonly scheduler: ManualScheduler;
  readonly messages: WorkerMessage[] = [];
  readonly session: SimSession;

  /** `wallNow`: the clock Step N slices its work by (default performance.now, the real one). */
  constructor(engine: SimEngine = realEngine, wallNow?: () => number, scheduler = new ManualScheduler()) {
    this.scheduler = scheduler;
    this.session = new SimSession({ engine, scheduler: this.scheduler, post: (m) => this.messages.push(m), ...(wallNow ? { wallNow } : {}) });
  }

  send(...messages: HostMessage[]): this {
    for (const m of messages) this.session.handle(m);
    return this;
  }

  /**
   * Lets the worker's event loop run what is due now: Step N runs in slices of real time (12 ms),
   * so on a busy machine the rest of a step comes on the scheduler, as in the worker.
   */
  settle(): this {
    this.scheduler.advance(0);
    return this;
  }

  /** Lets `ms` of wall-clock time pass for the run loop. */
  advance(ms: number): this {
    this.scheduler.advance(ms);
    return this;
  }

  get frame(): SimFrame {
    for (let i = this.messages.length - 1; i >= 0; i--) {
      const m = this.messages[i]!;
      if (m.type === 'frame') return m.frame;
    }
    throw new Error('no frame posted yet');
  }

  get layout(): SimLayout {
    for (let i = this.messages.length - 1; i >= 0; i--) {
      const m = this.messages[i]!;
      if (m.type === 'compiled' && m.layout) return m.layout;
    }
    throw new Error('nothing compiled yet');
  }

  of<T extends WorkerMessage['type']>(type: T): Extract<WorkerMessage, { type: T }>[] {
    return this.messages.filter((m): m is Extract<WorkerMessage, { type: T }> => m.type === type);
  }

  value(name: string): Value | undefined {
    const i = this.layout.variables.findIndex((v) => v.name.toUpperCase() === name.toUpperCase());
    return i < 0 ? undefined : this.frame.values[i];
  }

  /** Power byte of the element with this variable (first match) in the last frame. */
  powerOf(elementIndex: number, network = 0): number {
    return this.frame.elements[this.layout.elementOffsets[network]! + elementIndex]!;
  }
}
