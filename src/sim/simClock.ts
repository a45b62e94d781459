// The PLC's clock while simulating: set by the session before each scan, so stepping advances
// exactly one cycle per scan (virtual time) and Run follows the wall clock (real time).
import type { Clock } from '../engine/api';

export class SimClock implements Clock {
  private t = 0;
  now(): number {
    return this.t;
  }
  set(timeMs: number): void {
    this.t = timeMs;
  }
}
