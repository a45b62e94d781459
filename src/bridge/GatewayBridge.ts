/**
 * GatewayBridge: what the running simulation uses to take its I/O from the gateway.
 *
 *   const bridge = new GatewayBridge(client);          // client: a connected GatewayClient (role controller)
 *   bridge.inputImage(bindings)   -> Record<address, Value>
 *       The latest input values by IEC address (%IX0.0 -> true, %IW2 -> 1234) of the input points the
 *       program declares (`bindings` from checkBindings), for the next scan's input read, each
 *       converted to its variable's type (a WORD 65535 read into an INT variable gives -1). The
 *       gateway's other points are not the program's I/O and are never passed.
 *   bridge.sendOutputs(values)     values: Record<address, Value>, the scan's output image.
 *       Call after every scan (or every scan that changed it). Sent coalesced (OutputPump: at most
 *       once per gateway poll, the last image never dropped) and re-sent every 100 ms so the
 *       gateway's lease stays fed. Addresses the gateway does not have as outputs are left out;
 *       values wrap to the point's 16 bits.
 *   With a `driver` (the page: the simulation worker holds the link, src/bridge/workerRelay.ts),
 *   attach and drive() hand the exchange to the worker instead: it applies the inputs and sends
 *   the outputs and heartbeat itself, so a busy page cannot trip the lease.
 *   bridge.attach(sim, bindings)   on Run: wire the simulation store's setInputs/onOutputs (one at a time).
 *       When the operator pressed Run (`requestArm()` first), `arm` is sent before the first outputs.
 *   bridge.requestArm()            Run pressed as controller: the next attach arms the gateway. Nothing
 *       else arms: not a reconnect, a device coming back, an online change or a re-attach.
 *   bridge.arm()                   the operator's explicit Arm (Hardware panel) or a confirmed step.
 *   bridge.stop()                  pause/stop: detach, the gateway writes the safe state; heartbeats end.
 *   bridge.onInputs(cb)            cb(changed: Record<address, Value>) when inputs change; returns unsubscribe.
 *   bridge.canDrive                true when connected as controller and armed.
 *
 * Nothing is sent unless the client holds the controller lease; an observer only reads.
 *
 * The page's bridge is `gatewayLink.bridge` (src/bridge/gatewayLink.ts; undefined while no link is
 * open; `gatewayLink.subscribe` notifies changes). `attachSimulation` (below)
 * wires it to the simulation store's setInputs/onOutputs seams in one call, and
 * `checkBindings(project, gatewayLink.snapshot().points)` (src/bridge/mapping.ts) gives the
 * bindings and the mismatches to report before Run.
 */
import type { Value } from '../model/iecTypes';
import { canonicalAddress, type WireValue } from '../protocol/points';
import type { GatewayClient } from './GatewayClient';
import type { Binding } from './mapping';
import { OutputPump } from './outputPump';
import type { SimulationPorts } from './simulationLink';
import { fromWire, toWire } from './wireValues';
import type { ProgramDriver } from './workerSocket';

export class GatewayBridge {
  private lastOutputs: Record<string, WireValue> | undefined;
  private readonly pump: OutputPump;
  private detachSimulation: (() => void) | undefined;
  private armOnAttach = false;

  constructor(
    private readonly client: GatewayClient,
    private readonly driver?: ProgramDriver,
  ) {
    this.pump = new OutputPump((image) => this.client.sendOutputs(image), { periodMs: () => this.client.snapshot.pollMs ?? 100 });
  }

  /** True when the worker drives the hardware (the page only commands). */
  get drivenByWorker(): boolean {
    return this.driver !== undefined;
  }

  get canDrive(): boolean {
    return this.client.isController && this.client.snapshot.status?.armed !== false;
  }

  inputImage(bindings: readonly Binding[]): Record<string, Value> {
    const { values } = this.client.snapshot;
    const image: Record<string, Value> = {};
    for (const b of bindings) {
      const v = values[b.address];
      if (b.point.dir === 'in' && v !== undefined) image[b.address] = fromWire(b.varType, v);
    }
    return image;
  }

  sendOutputs(values: Readonly<Record<string, Value>>): void {
    const types = new Map(this.client.snapshot.points.filter((p) => p.dir === 'out').map((p) => [p.address, p.type]));
    const wire: Record<string, WireValue> = { ...this.lastOutputs };
    for (const [text, value] of Object.entries(values)) {
      const address = canonicalAddress(text);
      const type = address ? types.get(address) : undefined;
      if (address && type) wire[address] = toWire(type, value);
    }
    this.lastOutputs = wire;
    this.pump.offer(wire);
  }

  /**
   * With a driver: the worker exchanges images with the program (`run` while it runs, `step` for
   * confirmed stepping, fed between steps). Returns the function that ends it; undefined without a driver.
   */
  drive(bindings: readonly Binding[], kind: 'run' | 'step'): (() => void) | undefined {
    return this.driver?.drive(bindings, kind);
  }

  /**
   * Exchanges images with a running simulation (see attachSimulation). One simulation at a time:
   * attaching again replaces the previous link. Returns the function that detaches it.
   */
  attach(sim: SimulationPorts, bindings: readonly Binding[]): () => void {
    this.detachSimulation?.();
    if (this.armOnAttach) {
      this.armOnAttach = false;
      this.arm(); // the operator's Run: arm before the first outputs (the socket keeps the order)
    }
    const detach = this.driver?.drive(bindings, 'run') ?? attachSimulation(sim, this, bindings);
    const once = () => {
      if (this.detachSimulation !== once) return;
      this.detachSimulation = undefined;
      detach();
    };
    this.detachSimulation = once;
    return once;
  }

  /** Run was pressed: the next `attach` sends `arm` first (see the header). */
  requestArm(): void {
    this.armOnAttach = true;
  }

  /** Asks the gateway to arm (the operator's act); a refusal arrives as the view's lastError. */
  arm(): void {
    this.client.arm();
  }

  /** Pause/stop: detaches the simulation, ends heartbeats, and the gateway writes the safe state. */
  stop(): void {
    this.armOnAttach = false;
    this.detachSimulation?.();
    this.pump.stop();
    this.lastOutputs = undefined;
    this.client.stop();
  }

  onInputs(cb: (changed: Record<string, Value>) => void): () => void {
    return this.client.onMessage((m) => {
      if (m.t === 'inputs' || m.t === 'image') {
        const inputs = this.client.snapshot.points.filter((p) => p.dir === 'in');
        const changed: Record<string, Value> = {};
        for (const p of inputs) if (m.values[p.address] !== undefined) changed[p.address] = m.values[p.address] as WireValue;
        if (Object.keys(changed).length) cb(changed);
      }
    });
  }

}

// Glue between a running simulation and the gateway, for the simulation's Run/Pause/Stop:
//   const detach = attachSimulation(simStore.getState(), gatewayLink.bridge, report.bindings);  // on Run
//   detach(); bridge.stop();                                                                   // on Pause/Stop
// Inputs from the gateway go to the simulation's input image (converted to each bound variable's
// type); every output image the simulation reports goes to the gateway.
/** Starts exchanging images; returns the function that stops it (it does not send `stop`). */
export function attachSimulation(sim: SimulationPorts, bridge: GatewayBridge, bindings: readonly Binding[]): () => void {
  const bound = bindings.filter((b) => b.point.dir === 'in');
  const typed = (changed: Record<string, Value>) => {
    const image = bridge.inputImage(bound);
    const out: Record<string, Value> = {};
    for (const a of Object.keys(changed)) if (image[a] !== undefined) out[a] = image[a];
    return out;
  };
  sim.setInputs(bridge.inputImage(bound));
  const offInputs = bridge.onInputs((changed) => {
    const values = typed(changed);
    if (Object.keys(values).length) sim.setInputs(values);
  });
  const offOutputs = sim.onOutputs((outputs) => bridge.sendOutputs(outputs));
  return () => {
    offInputs();
    offOutputs();
  };
}
