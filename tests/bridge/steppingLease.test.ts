// Stepping with hardware attached (issue 6): confirmation first, then each step takes the
// gateway's inputs and writes its outputs, and the lease stays fed while paused between steps.
// A real gateway (simulated device) and the real GatewayClient/GatewayBridge; the simulation is a
// one-rung stand-in (Motor := Start) that scans when a step is performed.
import WebSocket from 'ws';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { GatewayBridge } from '../../src/bridge/GatewayBridge';
import { GatewayClient, type SocketLike } from '../../src/bridge/GatewayClient';
import { checkBindings, type Binding } from '../../src/bridge/mapping';
import type { SimulationPorts } from '../../src/bridge/simulationLink';
import { SteppingLease, type StepContext, type StepRequest } from '../../src/bridge/steppingLease';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Value } from '../../src/model/iecTypes';
import { eventually } from '../gateway/helpers';

/**
 * The gateway's lease: ten of the bridge's 100 ms heartbeats, so that a busy machine (a heartbeat
 * late by a few hundred ms) does not trip it; the waits below that prove "still fed" or "nothing
 * re-feeds it" are multiples of it.
 */
const WATCHDOG_MS = 1000;
const config = resolveConfig({ watchdogMs: WATCHDOG_MS, simulated: { modbusPort: null } });
const factory = (url: string) => new WebSocket(url) as unknown as SocketLike;
const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

/** Motor := Start, scanned on each performed step; the input image is what setInputs last gave. */
class OneRungSim implements SimulationPorts {
  inputs: Record<string, Value> = { '%IX0.0': false };
  outputs: Record<string, Value> = { '%QX0.0': false };
  readonly performed: StepRequest[] = [];
  readonly events: string[] = [];
  private listener: ((o: Readonly<Record<string, Value>>, scan: number) => void) | undefined;
  setInputs(values: Readonly<Record<string, Value>>): void {
    this.events.push('inputs');
    this.inputs = { ...this.inputs, ...values };
  }
  onOutputs(listener: (o: Readonly<Record<string, Value>>, scan: number) => void): () => void {
    this.listener = listener;
    listener(this.outputs, 0); // like the worker: the current image on subscribe
    return () => (this.listener = undefined);
  }
  get subscribed(): boolean {
    return this.listener !== undefined;
  }
  context(bindings: readonly Binding[]): StepContext {
    return {
      sim: this,
      bindings: () => bindings,
      perform: (request) => {
        this.events.push('scan');
        this.performed.push(request);
        this.outputs = { '%QX0.0': this.inputs['%IX0.0'] === true };
        this.listener?.(this.outputs, this.performed.length);
      },
    };
  }
}

describe('SteppingLease with a real gateway', () => {
  let gw: RunningGateway;
  let client: GatewayClient;
  let bridge: GatewayBridge;
  let bindings: readonly Binding[];
  let controller: boolean;
  let lease: SteppingLease;
  const written = () => gw.simulated?.writtenValues().get('%QX0.0');

  beforeAll(async () => {
    gw = await startGateway({ port: 0, config, distDir: null });
  });
  afterAll(() => gw?.close());

  const connect = async () => {
    client = new GatewayClient({ socketUrl: `ws://127.0.0.1:${gw.port}/io`, token: gw.token, role: 'controller', socketFactory: factory });
    client.connect();
    await eventually(() => client.snapshot.link === 'open' && client.snapshot.status !== null, 10_000, 'open');
    bridge = new GatewayBridge(client);
    controller = true;
    lease = new SteppingLease(() => (controller && client.isController ? bridge : undefined));
    const project = newProject('Motor', {
      pous: [newPou('Main', { variables: [variable('Start', 'BOOL', { location: '%IX0.0' }), variable('Motor', 'BOOL', { location: '%QX0.0' })] })],
    });
    bindings = checkBindings(project, client.snapshot.points).bindings;
  };
  /** Connected, Start on at the device, one confirmed step taken: stepping mode with the output on. */
  const steppingWithOutputOn = async () => {
    await connect();
    const sim = new OneRungSim();
    client.simulate({ '%IX0.0': true });
    await eventually(() => client.snapshot.values['%IX0.0'] === true, 10_000, 'input');
    lease.step({ kind: 'scans', scans: 1 }, sim.context(bindings));
    lease.confirm();
    await eventually(() => written() === true, 10_000, 'output on');
    return sim;
  };
  afterEach(async () => {
    lease.end('stop');
    client.simulate({ '%IX0.0': false });
    await eventually(() => written() === false && client.snapshot.values['%IX0.0'] === false, 10_000, 'clean device');
    client.disconnect();
  });

  it('steps at once when no hardware is attached as controller', async () => {
    await connect();
    controller = false;
    const sim = new OneRungSim();
    expect(lease.step({ kind: 'scans', scans: 1 }, sim.context(bindings))).toBe('stepped');
    expect(sim.performed).toEqual([{ kind: 'scans', scans: 1 }]);
    expect(lease.snapshot().phase).toBe('off');
    expect(sim.events).toEqual(['scan']); // no input image taken from the gateway
  });

  it('asks before the first step; cancelling does not step and writes nothing', async () => {
    await connect();
    const sim = new OneRungSim();
    sim.inputs['%IX0.0'] = true; // would switch the output on if it ran
    expect(lease.step({ kind: 'network' }, sim.context(bindings))).toBe('asked');
    expect(lease.snapshot()).toEqual({ phase: 'confirming', request: { kind: 'network' } });
    expect(lease.step({ kind: 'scans', scans: 1 }, sim.context(bindings))).toBe('ignored');
    lease.decline();
    expect(lease.snapshot().phase).toBe('off');
    expect(sim.performed).toEqual([]);
    expect(sim.subscribed).toBe(false);
    await sleep(WATCHDOG_MS);
    expect(written()).toBe(false);
    expect(client.snapshot.status?.watchdog.state).toBe('idle');
    expect(client.snapshot.status?.armed).toBe(false); // declining does not arm
  });

  it('once confirmed, each step reads the gateway inputs first, writes its outputs, and keeps the lease fed between steps', async () => {
    await connect();
    const sim = new OneRungSim();
    client.simulate({ '%IX0.0': true });
    await eventually(() => client.snapshot.values['%IX0.0'] === true, 10_000, 'input set on the device');
    expect(lease.step({ kind: 'scans', scans: 1 }, sim.context(bindings))).toBe('asked');
    expect(client.snapshot.status?.armed).toBe(false); // the gateway starts disarmed
    lease.confirm(); // the operator's confirmation arms it
    expect(lease.snapshot().phase).toBe('stepping');
    expect(sim.events).toEqual(['inputs', 'scan']);
    expect(sim.inputs['%IX0.0']).toBe(true);
    // The device has the output before the gateway's status (armed) reaches the client: wait for both.
    await eventually(() => written() === true && client.snapshot.status?.armed === true, 10_000, 'output on the device, armed');

    // Paused in stepping mode for several watchdog periods: still armed, fed, output kept.
    await sleep(WATCHDOG_MS * 2);
    expect(client.snapshot.status?.armed).toBe(true);
    expect(client.snapshot.status?.watchdog.state).toBe('fed');
    expect(written()).toBe(true);

    // The next step does not ask again and sees the input the device has now.
    client.simulate({ '%IX0.0': false });
    await eventually(() => client.snapshot.values['%IX0.0'] === false, 10_000, 'input cleared');
    expect(lease.step({ kind: 'scans', scans: 1 }, sim.context(bindings))).toBe('stepped-on-hardware');
    expect(sim.events).toEqual(['inputs', 'scan', 'inputs', 'scan']);
    await eventually(() => written() === false, 10_000, 'output off on the device');
    expect(client.snapshot.status?.watchdog.state).toBe('fed');
  });

  it('Reset (stop) writes the safe state and ends the heartbeat; the next step asks again', async () => {
    const sim = await steppingWithOutputOn();
    lease.end('stop');
    expect(sim.subscribed).toBe(false);
    await eventually(() => written() === false && client.snapshot.status?.watchdog.state === 'idle', 10_000, 'safe state');
    await sleep(WATCHDOG_MS * 1.5);
    expect(client.snapshot.status?.watchdog.state).toBe('idle'); // nothing re-feeds it
    expect(written()).toBe(false);
    expect(lease.step({ kind: 'scans', scans: 1 }, sim.context(bindings))).toBe('asked');
    lease.decline();
    expect(client.snapshot.status).toMatchObject({ armed: false, disarm: { cause: 'stop' } });
  });

  it('the Safe state (stop) while stepping latches: later steps do not re-arm, their outputs are refused', async () => {
    const sim = await steppingWithOutputOn();
    client.stop(); // the Hardware panel's Safe state, the lease still feeding
    await eventually(() => written() === false && client.snapshot.status?.armed === false, 10_000, 'safe state');
    expect(lease.step({ kind: 'scans', scans: 1 }, sim.context(bindings))).toBe('stepped-on-hardware');
    await eventually(() => client.snapshot.lastError?.code === 'disarmed', 10_000, 'outputs refused');
    await sleep(WATCHDOG_MS * 1.5);
    expect(written()).toBe(false);
    expect(client.snapshot.status?.disarm?.cause).toBe('stop');
  });

  it('Run hands the lease over without a safe-state gap', async () => {
    const sim = await steppingWithOutputOn();
    lease.end('run');
    expect(lease.snapshot().phase).toBe('off');
    expect(sim.subscribed).toBe(false);
    await sleep(WATCHDOG_MS * 1.5);
    expect(written()).toBe(true); // no stop was sent; the bridge keeps the image until the run attaches
    bridge.stop();
  });

  it('losing the controller role ends stepping mode', async () => {
    await connect();
    const sim = new OneRungSim();
    lease.step({ kind: 'scans', scans: 1 }, sim.context(bindings));
    lease.confirm();
    expect(lease.snapshot().phase).toBe('stepping');
    controller = false;
    lease.hardwareChanged();
    expect(lease.snapshot().phase).toBe('off');
    expect(sim.subscribed).toBe(false);
    // Without hardware the next step just runs the simulation.
    expect(lease.step({ kind: 'scans', scans: 2 }, sim.context(bindings))).toBe('stepped');
  });
});
