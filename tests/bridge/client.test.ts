// The browser client and bridge against a real gateway (the `ws` package stands in for the browser's WebSocket).
import WebSocket from 'ws';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { gatewaySocketUrl, tokenFromFragment } from '../../src/bridge/connection';
import { GatewayBridge } from '../../src/bridge/GatewayBridge';
import { GatewayClient, type SocketLike } from '../../src/bridge/GatewayClient';
import { checkBindings } from '../../src/bridge/mapping';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Value } from '../../src/model/iecTypes';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { eventually } from '../gateway/helpers';

const factory = (url: string) => new WebSocket(url) as unknown as SocketLike;
/** The lease: 20 heartbeats (50 ms) long, so a busy machine does not trip it. */
const WATCHDOG_MS = 1000;
const config = resolveConfig({ watchdogMs: WATCHDOG_MS, simulated: { modbusPort: null } });

describe('gateway URL and token', () => {
  it('derives the socket URL from the page URL and reads the token from the fragment', () => {
    expect(gatewaySocketUrl('http://127.0.0.1:8080/#token=abc')).toBe('ws://127.0.0.1:8080/io');
    expect(gatewaySocketUrl('127.0.0.1:9000')).toBe('ws://127.0.0.1:9000/io');
    expect(gatewaySocketUrl('https://localhost:8443/app')).toBe('wss://localhost:8443/io');
    expect(gatewaySocketUrl('not a url at all')).toBeUndefined();
    expect(tokenFromFragment('#token=Xy_z-1')).toBe('Xy_z-1');
    expect(tokenFromFragment('#other=1')).toBeUndefined();
  });
});

describe('GatewayClient and GatewayBridge', () => {
  let gw: RunningGateway;
  beforeAll(async () => {
    gw = await startGateway({ port: 0, config, distDir: null });
  });
  afterAll(() => gw?.close());

  const client = (role: 'controller' | 'observer', token = gw.token) =>
    new GatewayClient({ socketUrl: `ws://127.0.0.1:${gw.port}/io`, token, role, socketFactory: factory, retryFirstMs: 50 });

  it('connects, gets the points and the image, and feeds inputs to the bridge', async () => {
    const c = client('controller');
    c.connect();
    await eventually(() => c.snapshot.link === 'open' && c.snapshot.status !== null, 10_000, 'open');
    expect(c.snapshot.role).toBe('controller');
    expect(c.snapshot.points).toHaveLength(40);
    const bridge = new GatewayBridge(c);
    const seen: Record<string, unknown>[] = [];
    const off = bridge.onInputs((changed) => seen.push(changed));
    c.simulate({ '%IX0.4': true, '%IW1': 65535 });
    const bound = (variable: string, varType: string, address: string, type: 'BOOL' | 'WORD') =>
      ({ pou: 'Main', variable, varType, address, point: { address, type, dir: 'in', device: 'sim' } }) as const;
    await eventually(() => bridge.inputImage([bound('Sensor', 'BOOL', '%IX0.4', 'BOOL')])['%IX0.4'] === true, 10_000, 'input');
    expect(bridge.inputImage([bound('Raw', 'WORD', '%IW1', 'WORD')])['%IW1']).toBe(65535);
    expect(bridge.inputImage([bound('Level', 'INT', '%IW1', 'WORD')])['%IW1']).toBe(-1);
    // Only the points the program declares: the gateway's other inputs are not passed.
    expect(Object.keys(bridge.inputImage([bound('Sensor', 'BOOL', '%IX0.4', 'BOOL')]))).toEqual(['%IX0.4']);
    expect(bridge.inputImage([])).toEqual({});
    expect(seen.some((s) => s['%IX0.4'] === true)).toBe(true);
    off();

    // The gateway starts disarmed: outputs are refused until the controller arms.
    bridge.sendOutputs({ '%QX0.6': true });
    await eventually(() => c.snapshot.lastError?.code === 'disarmed', 10_000, 'refused while disarmed');
    expect(gw.simulated?.writtenValues().get('%QX0.6')).toBe(false);
    bridge.arm();
    await eventually(() => c.snapshot.status?.armed === true, 10_000, 'armed');
    expect(c.snapshot.lastError).toBeNull(); // the refusal is history once armed
    bridge.sendOutputs({ '%qx0.6': true, '%QW2': -2, '%IX0.0': true, '%QX9.9': true });
    // The heartbeat may re-send the image of the disarmed moment ({%QX0.6: TRUE} only) just before
    // this image: wait for the image sent, not for its first point.
    const written = () => gw.simulated?.writtenValues();
    await eventually(() => written()?.get('%QX0.6') === true && written()?.get('%QW2') === 65534, 10_000, 'outputs written');
    expect([written()?.get('%QX0.6'), written()?.get('%QW2')]).toEqual([true, 65534]);
    expect(gw.simulated?.inputValues().get('%IX0.0')).toBe(false); // inputs are not outputs
    // Heartbeats keep the lease fed while the simulation sends nothing new: for over twice its
    // length, without a trip (heartbeats every 50 ms; a trip would need a 1 s stall of this process).
    await new Promise((r) => setTimeout(r, 2.5 * WATCHDOG_MS));
    expect(c.snapshot.status?.watchdog.state).toBe('fed');
    expect(gw.simulated?.writtenValues().get('%QX0.6')).toBe(true);

    bridge.stop();
    await eventually(() => c.snapshot.values['%QX0.6'] === false && c.snapshot.status?.watchdog.state === 'idle', 10_000, 'stopped');
    c.disconnect();
    expect(c.snapshot.link).toBe('idle');
  });

  it('links a simulation: gateway inputs reach its input image typed per variable, its outputs reach the device', async () => {
    const c = client('controller');
    c.connect();
    await eventually(() => c.snapshot.link === 'open', 10_000, 'open');
    const bridge = new GatewayBridge(c);
    const received: Record<string, unknown>[] = [];
    let emit: ((o: Readonly<Record<string, Value>>, scan: number) => void) | undefined;
    const sim = {
      setInputs: (v: Readonly<Record<string, Value>>) => received.push({ ...v }),
      onOutputs: (l: (o: Readonly<Record<string, Value>>, scan: number) => void) => {
        emit = l;
        return () => (emit = undefined);
      },
    };
    const report = checkBindings(
      newProject('Motor', { pous: [newPou('Main', { variables: [variable('Start', 'BOOL', { location: '%IX0.0' }), variable('Level', 'INT', { location: '%IW0' }), variable('Motor', 'BOOL', { location: '%QX0.0' })] })] }),
      c.snapshot.points,
    );
    bridge.requestArm(); // Run pressed: the attach arms first
    const detach = bridge.attach(sim, report.bindings);
    expect(received[0]).toEqual({ '%IX0.0': false, '%IW0': 0 }); // only the program's own inputs
    await eventually(() => c.snapshot.status?.armed === true, 10_000, 'armed by Run');
    c.simulate({ '%IX0.0': true, '%IW0': 65000 });
    await eventually(() => received.some((r) => r['%IX0.0'] === true && r['%IW0'] === 65000 - 65536), 10_000, 'typed inputs');
    emit?.({ '%QX0.0': true }, 1);
    await eventually(() => gw.simulated?.writtenValues().get('%QX0.0') === true, 10_000, 'output on the device');
    detach();
    expect(emit).toBeUndefined();
    bridge.stop();
    await eventually(() => gw.simulated?.writtenValues().get('%QX0.0') === false, 10_000, 'safe state');
    await eventually(() => c.snapshot.status?.disarm?.cause === 'stop', 10_000, 'disarmed by stop');
    // A re-attach (reconnect, online change) without a new Run does not arm: outputs stay refused.
    bridge.attach(sim, report.bindings);
    emit?.({ '%QX0.0': true }, 2);
    await eventually(() => c.snapshot.lastError?.code === 'disarmed', 10_000, 'refused after stop');
    expect(c.snapshot.status?.armed).toBe(false);
    expect(gw.simulated?.writtenValues().get('%QX0.0')).toBe(false);
    bridge.stop();
    c.disconnect();
  });

  it('becomes an observer when another controller holds the lease, and sends nothing as observer', async () => {
    const a = client('controller');
    const b = client('controller');
    a.connect();
    await eventually(() => a.snapshot.link === 'open', 10_000, 'a open');
    b.connect();
    await eventually(() => b.snapshot.link === 'open', 10_000, 'b open');
    expect(b.snapshot.role).toBe('observer');
    expect(b.sendOutputs({ '%QX0.0': true })).toBe(false);
    a.disconnect();
    b.disconnect();
  });

  it('stops retrying when the gateway refuses the token, and says why', async () => {
    const c = client('controller', 'definitely-not-the-token');
    c.connect();
    await eventually(() => c.snapshot.link === 'refused', 10_000, 'refused');
    expect(c.snapshot.problem).toMatch(/wrong token/);
  });

  it('reconnects after the gateway restarts on the same port', async () => {
    const port = gw.port;
    const c = client('observer');
    c.connect();
    await eventually(() => c.snapshot.link === 'open', 10_000, 'open');
    await gw.close();
    await eventually(() => c.snapshot.link === 'retrying', 10_000, 'retrying');
    gw = await startGateway({ port, config, distDir: null, token: gw.token });
    await eventually(() => c.snapshot.link === 'open', 15_000, 'open again');
    expect(c.snapshot.points).toHaveLength(40);
    c.disconnect();
  });
});
