/**
 * SteppingLease: stepping the simulation while this page is the gateway's controller (issue 6:
 * "stepping with hardware attached asks for confirmation and keeps the lease fed").
 *
 *   const lease = new SteppingLease(() => controllerBridgeOrUndefined);
 *   lease.step(request, ctx)   Step scan / Step N / Step network pressed.
 *       No hardware as controller: the step runs at once ('stepped').
 *       Otherwise the first step after a pause asks ('asked': the view's phase is 'confirming';
 *       the UI shows the confirmation) and nothing runs until `confirm()`.
 *       In confirmed stepping mode each step first gives the simulation the gateway's current
 *       input image, then runs; the scan's output image goes to the gateway ('stepped-on-hardware').
 *   lease.confirm()            runs the pending step on the hardware and enters stepping mode: the
 *       gateway is armed (the confirmation is the operator's deliberate act), the output image of every scan is sent, and the bridge re-sends the last one as a heartbeat
 *       (GatewayBridge, every 100 ms, well within the gateway's 200–5000 ms watchdog).
 *   lease.decline()            the confirmation was cancelled: no step, nothing written.
 *   lease.end(reason)          Run ('run': the running simulation takes the lease over, nothing is
 *       stopped), Reset / Warm restart / a fault / "end stepping" ('stop': the gateway writes the
 *       safe state), link lost ('disconnected': heartbeats end; the gateway already wrote the safe state).
 *   lease.hardwareChanged()    call on every gateway link change: losing the controller role ends
 *       stepping mode.
 *
 * Only the confirmation arms the gateway: a gateway disarmed later while stepping (Safe state, a
 * watchdog trip, a device lost) is never re-armed here; the Hardware panel shows why and offers Arm.
 */
import type { Value } from '../model/iecTypes';
import type { Binding } from './mapping';
import type { SimulationPorts } from './simulationLink';

export type StepRequest =
  | { readonly kind: 'scans'; readonly scans: number }
  /**
   * One network (an ST/IL statement); `into`: a call stops before its body's first network or
   * statement (step into); `out`: the rest of the body runs, to the caller's next stop (step out).
   */
  | { readonly kind: 'network'; readonly into?: boolean; readonly out?: boolean };

/** off: stepping does not touch the hardware (not asked yet, or no hardware); confirming: the question is open; stepping: confirmed. */
export type SteppingPhase = 'off' | 'confirming' | 'stepping';

export interface SteppingView {
  readonly phase: SteppingPhase;
  /** The step waiting for the confirmation. */
  readonly request: StepRequest | undefined;
}

/** The parts of GatewayBridge the lease uses. */
export interface LeaseBridge {
  inputImage(bindings: readonly Binding[]): Record<string, Value>;
  sendOutputs(values: Readonly<Record<string, Value>>): void;
  arm(): void;
  stop(): void;
  /** The simulation worker exchanges the images itself (GatewayBridge.drive); undefined: the page does. */
  drive?(bindings: readonly Binding[], kind: 'run' | 'step'): (() => void) | undefined;
}

export interface StepContext {
  readonly sim: SimulationPorts;
  /** Program variables bound to gateway points (checkBindings), read when the hardware is used. */
  bindings(): readonly Binding[];
  /** Runs the step in the simulation (simStore.step / stepNetwork with the current document). */
  perform(request: StepRequest): void;
}

export type EndReason = 'run' | 'stop' | 'disconnected';
export type StepOutcome = 'stepped' | 'asked' | 'stepped-on-hardware' | 'ignored';

const OFF: SteppingView = { phase: 'off', request: undefined };

export class SteppingLease {
  private view: SteppingView = OFF;
  private pending: StepContext | undefined;
  private feeding: { readonly bridge: LeaseBridge; readonly detach: () => void } | undefined;
  private readonly listeners = new Set<() => void>();

  /** @param controller the bridge while this page holds the controller lease, else undefined. */
  constructor(private readonly controller: () => LeaseBridge | undefined) {}

  snapshot = (): SteppingView => this.view;

  subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  step(request: StepRequest, ctx: StepContext): StepOutcome {
    const bridge = this.controller();
    if (!bridge) {
      if (this.view.phase !== 'off') this.end('disconnected');
      ctx.perform(request);
      return 'stepped';
    }
    if (this.view.phase === 'confirming') return 'ignored'; // the question is still open
    if (this.view.phase === 'stepping' && this.feeding?.bridge === bridge) {
      this.exchange(bridge, request, ctx);
      return 'stepped-on-hardware';
    }
    this.stopFeeding();
    this.pending = ctx;
    this.set({ phase: 'confirming', request });
    return 'asked';
  }

  /** The user confirmed: the pending step runs on the hardware, and later steps do too without asking. */
  confirm(): void {
    const ctx = this.pending;
    const request = this.view.request;
    if (this.view.phase !== 'confirming' || !ctx || !request) return;
    this.pending = undefined;
    const bridge = this.controller();
    if (!bridge) {
      // The link went away while the question was open: step the simulation alone.
      this.set(OFF);
      ctx.perform(request);
      return;
    }
    // The operator confirmed: arm before the first outputs. Every output image the simulation
    // reports goes to the gateway; the worker reports the current one at once, so the bridge's
    // heartbeat starts right away.
    bridge.arm();
    const detach = bridge.drive?.(ctx.bindings(), 'step') ?? ctx.sim.onOutputs((outputs) => bridge.sendOutputs(outputs));
    this.feeding = { bridge, detach };
    this.set({ phase: 'stepping', request: undefined });
    this.exchange(bridge, request, ctx);
  }

  /** The user cancelled the confirmation: the step does not run. */
  decline(): void {
    if (this.view.phase !== 'confirming') return;
    this.pending = undefined;
    this.set(OFF);
  }

  end(reason: EndReason): void {
    const feeding = this.feeding;
    this.pending = undefined;
    this.stopFeeding();
    // Stop and link loss: the gateway writes the safe state (or already did) and heartbeats end.
    // Run: the running simulation's link takes the lease over without a gap.
    if (feeding && reason !== 'run') feeding.bridge.stop();
    if (this.view.phase !== 'off') this.set(OFF);
  }

  hardwareChanged(): void {
    if (this.view.phase === 'off') return;
    const bridge = this.controller();
    if (!bridge || (this.feeding && this.feeding.bridge !== bridge)) this.end('disconnected');
  }

  private exchange(bridge: LeaseBridge, request: StepRequest, ctx: StepContext): void {
    const inputs = ctx.bindings().filter((b) => b.point.dir === 'in');
    ctx.sim.setInputs(bridge.inputImage(inputs));
    ctx.perform(request);
  }

  private stopFeeding(): void {
    this.feeding?.detach();
    this.feeding = undefined;
  }

  private set(view: SteppingView): void {
    this.view = view;
    this.listeners.forEach((l) => l());
  }
}
