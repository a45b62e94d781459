/**
 * OutputPump: how a controller sends its output image to the gateway (issue 21, items 4 and 5).
 *
 *   const pump = new OutputPump(send, { periodMs: () => welcome.pollMs ?? 100 });
 *   pump.offer(image)   after every scan that changed the outputs (any rate: 1 ms cycles included)
 *   pump.stop()         pause/stop/link lost: nothing more is sent
 *
 * Coalesced: the latest image is sent at most once per period (the gateway's fastest poll: it could
 * not write more often anyway), so a program changing its outputs every 1 ms scan sends ~10-20
 * messages per second instead of 1,000. Never dropping the last: an image offered inside a period
 * is sent at the period's end, so the final image after a burst always reaches the gateway. An
 * image offered after a quiet period goes out at once. With nothing new, the last image is sent
 * again every `heartbeatMs` (100 ms, well inside the 200-5000 ms watchdog): the lease heartbeat.
 * A send that fails (not the controller at the moment) is retried at the next period.
 */
import type { WireValue } from '../protocol/points';

export type WireImage = Readonly<Record<string, WireValue>>;

export interface PumpOptions {
  /** Least time between two sends (ms), read at every send (it comes with the gateway's welcome). */
  readonly periodMs?: () => number;
  readonly heartbeatMs?: number;
  readonly now?: () => number;
}

export const DEFAULT_PERIOD_MS = 100;
export const HEARTBEAT_MS = 100;
/** Never faster than this, whatever the gateway's poll. */
const MIN_PERIOD_MS = 10;

export class OutputPump {
  private latest: WireImage | undefined;
  private dirty = false;
  private lastSentAt = -Infinity;
  private timer: ReturnType<typeof setTimeout> | undefined;
  private readonly heartbeatMs: number;
  private readonly now: () => number;

  constructor(
    private readonly send: (image: WireImage) => boolean,
    private readonly opts: PumpOptions = {},
  ) {
    this.heartbeatMs = opts.heartbeatMs ?? HEARTBEAT_MS;
    this.now = opts.now ?? (() => Date.now());
  }

  get running(): boolean {
    return this.latest !== undefined;
  }

  /** The image last offered (what the next send carries). */
  get image(): WireImage | undefined {
    return this.latest;
  }

  private period(): number {
    return Math.max(MIN_PERIOD_MS, Math.min(HEARTBEAT_MS, this.opts.periodMs?.() ?? DEFAULT_PERIOD_MS));
  }

  offer(image: WireImage): void {
    this.latest = image;
    this.dirty = true;
    if (this.now() - this.lastSentAt >= this.period()) this.flush();
    this.timer ??= setTimeout(() => this.tick(), this.period());
  }

  /** Every period while running: the coalesced image if one waits, else the heartbeat when due. */
  private tick(): void {
    this.timer = undefined;
    if (!this.latest) return;
    const since = this.now() - this.lastSentAt;
    // An offer may have sent the image since this tick was scheduled: never two sends within a period.
    if (since < this.period()) {
      this.timer = setTimeout(() => this.tick(), this.period() - since);
      return;
    }
    if (this.dirty || since >= this.heartbeatMs * 0.9) this.flush();
    this.timer = setTimeout(() => this.tick(), this.period());
  }

  private flush(): void {
    if (!this.latest || !this.send(this.latest)) return;
    this.dirty = false;
    this.lastSentAt = this.now();
  }

  stop(): void {
    clearTimeout(this.timer);
    this.timer = undefined;
    this.latest = undefined;
    this.dirty = false;
  }
}
