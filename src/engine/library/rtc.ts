// RTC, the real-time clock of MATIEC's lib/rtc.txt (OpenPLC Editor's palette): Q is a copy of IN;
// with IN OFF, CDT is the current date and time; on IN's rising edge PDT is loaded, and while IN
// stays ON, CDT is PDT plus the time since. MATIEC's CURRENT_TIME is the runtime's clock; the
// simulator's is its PLC clock, which starts at DT#1970-01-01-00:00:00 with the first scan.
import { StandardFb } from './fbBase';

export class RTC extends StandardFb {
  readonly fbType = 'RTC';
  IN = false;
  PDT = 0;
  Q = false;
  CDT = 0;
  PREV_IN = false;
  OFFSET = 0;
  CURRENT_TIME = 0;
  execute(nowMs: number): void {
    this.CURRENT_TIME = Math.round(nowMs);
    if (this.IN) {
      if (!this.PREV_IN) this.OFFSET = this.PDT - this.CURRENT_TIME;
      this.CDT = this.CURRENT_TIME + this.OFFSET;
    } else this.CDT = this.CURRENT_TIME;
    this.Q = this.IN;
    this.PREV_IN = this.IN;
  }
  reset(): void {
    this.IN = this.Q = this.PREV_IN = false;
    this.PDT = this.CDT = this.OFFSET = this.CURRENT_TIME = 0;
  }
}
