// A scheduler on a hand-turned clock, so the simulation loop's pacing is tested without waiting.
import type { Scheduler } from '../../src/sim/scheduler';

interface Task {
  readonly at: number;
  readonly seq: number;
  readonly fn: () => void;
}

export class ManualScheduler implements Scheduler {
  private t = 0;
  private seq = 0;
  private tasks: Task[] = [];

  now(): number {
    return this.t;
  }

  schedule(fn: () => void, ms: number): () => void {
    const task = { at: this.t + Math.max(0, ms), seq: this.seq++, fn };
    this.tasks.push(task);
    return () => {
      this.tasks = this.tasks.filter((x) => x !== task);
    };
  }

  /** The wall clock jumps without any timer firing (a stalled worker). */
  stall(ms: number): void {
    this.t += ms;
  }

  get pending(): number {
    return this.tasks.length;
  }

  /** Moves the clock forward, running every task that falls due (at most maxTasks, against runaway 0 ms loops). */
  advance(ms: number, maxTasks = 100_000): void {
    const target = this.t + ms;
    for (let n = 0; n < maxTasks; n++) {
      const next = this.tasks.reduce<Task | undefined>((a, b) => (!a || b.at < a.at || (b.at === a.at && b.seq < a.seq) ? b : a), undefined);
      if (!next || next.at > target) break;
      this.tasks = this.tasks.filter((x) => x !== next);
      this.t = Math.max(this.t, next.at);
      next.fn();
    }
    this.t = Math.max(this.t, target);
  }
}
