// Issue 21 items 4 and 5 in Node: the page's GatewayClient speaking through the worker's relay
// (workerSocket.ts <-> workerRelay.ts, joined here by an in-process transport), and the coalescing
// OutputPump, against a real gateway; coils are read back from its simulated device over Modbus TCP.
import WebSocket from 'ws';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { GatewayBridge } from '../../src/bridge/GatewayBridge';
import { GatewayClient, type SocketLike } from '../../src/bridge/GatewayClient';
import { checkBindings } from '../../src/bridge/mapping';
import { GatewayRelay } from '../../src/bridge/workerRelay';
import { workerDriver, workerSocketFactory } from '../../src/bridge/workerSocket';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import type { Value } from '../../src/model/iecTypes';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { SimTransport } from '../../src/sim/host';
import type { SimFrame, WorkerMessage } from '../../src/sim/protocol';
import { eventually, mbpoll, mbpollValues } from '../gateway/helpers';

/** Counts the `outputs` frames a socket sends. */
function countingFactory(counter: { outputs: number }) {
  return (url: string) => {
    const ws = new WebSocket(url);
    const send = ws.send.bind(ws);
    (ws as unknown as { send(data: string): void }).send = (data: string) => {
      if (data.includes('"t":"outputs"')) counter.outputs++;
      send(data);
    };
    return ws as unknown as SocketLike;
  };
}

const frame = (mode: SimFrame['mode']) => ({ mode }) as SimFrame;

/** The worker's relay and the page's transport to it, as the simulator's worker and host connect them. */
function relayInWorker(...args: ConstructorParameters<typeof GatewayRelay> extends [unknown, ...infer R] ? R : never) {
  const listeners = new Set<(m: WorkerMessage) => void>();
  const relay = new GatewayRelay((m) => listeners.forEach((l) => l(m)), ...args);
  const transport: SimTransport = {
    send: (m) => {
      if (m.type.startsWith('gw')) queueMicrotask(() => relay.handle(m as Parameters<GatewayRelay['handle']>[0]));
    },
    listen: (l) => {
      listeners.add(l);
      return () => listeners.delete(l);
    },
    terminate: () => undefined,
  };
  return { relay, transport };
}

describe('controller outputs from where the program runs', () => {
  let gw: RunningGateway;
  beforeAll(async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ watchdogMs: 500, simulated: { modbusPort: 0 } }), distDir: null });
  });
  afterAll(() => gw?.close());
  const coil = async (n: number) => mbpollValues(await mbpoll(gw.simulated?.modbusServerPort ?? 0, ['-t', '0', '-r', String(n), '-c', '1', '127.0.0.1']))[0];
  const project = newProject('P', { pous: [newPou('Main', { variables: [variable('Start', 'BOOL', { location: '%IX0.2' }), variable('Q', 'BOOL', { location: '%QX0.1' })] })] });

  it('the relay applies inputs, sends a 1 kHz output stream coalesced with the last image, and ends the drive with stop when the program stops', async () => {
    const sent = { outputs: 0 };
    const inputs: Record<string, Value>[] = [];
    let wantsOutputs = false;
    const { relay, transport } = relayInWorker(countingFactory(sent), {
      setInputs: (v) => inputs.push({ ...v }),
      wantOutputs: (on) => (wantsOutputs = on),
    });
    const ended: string[] = [];
    const driver = workerDriver(transport);
    driver.onEnded((r) => ended.push(r));
    const client = new GatewayClient({ socketUrl: `ws://127.0.0.1:${gw.port}/io`, token: gw.token, role: 'controller', socketFactory: workerSocketFactory(transport) });
    client.connect();
    await eventually(() => client.snapshot.link === 'open' && client.snapshot.status !== null, 5000, 'open through the relay');
    expect(client.snapshot).toMatchObject({ role: 'controller', pollMs: 50 });
    const bridge = new GatewayBridge(client, driver);
    transport.send({ type: 'gwPrograms', ids: ['P'] });
    bridge.requestArm();
    const { bindings } = checkBindings(project, client.snapshot.points);
    const detach = bridge.attach({ setInputs: () => undefined, onOutputs: () => () => undefined }, bindings);
    relay.frame(frame('running'));
    await eventually(() => wantsOutputs && client.snapshot.status?.armed === true, 5000, 'armed, outputs wanted');

    // Inputs go from the socket straight to the program (typed, only its own).
    client.simulate({ '%IX0.2': true, '%IX0.3': true });
    await eventually(() => inputs.some((i) => i['%IX0.2'] === true), 5000, 'input applied by the relay');
    expect(inputs.every((i) => !('%IX0.3' in i))).toBe(true);

    // A program that changes Q every 1 ms scan for 2 s, then holds it TRUE. Outputs of another program never drive.
    relay.outputs({ '%QX0.1': true }, 'someone else');
    let scans = 0;
    const t0 = Date.now();
    await new Promise<void>((done) => {
      const timer = setInterval(() => {
        scans++;
        relay.outputs({ '%QX0.1': scans % 2 === 0 }, 'P');
        if (Date.now() - t0 >= 2000) {
          clearInterval(timer);
          relay.outputs({ '%QX0.1': true }, 'P');
          done();
        }
      }, 1);
    });
    const elapsed = Date.now() - t0;
    const sentInBurst = sent.outputs;
    await eventually(async () => (await coil(1)) === 1, 5000, 'the last image on the device');
    // At most one image per 50 ms poll (plus the first at once and the last after the burst).
    expect(sentInBurst).toBeLessThanOrEqual(Math.ceil(elapsed / 50) + 2);
    expect(client.snapshot.link).toBe('open');
    expect(client.snapshot.lastError).toBeNull();

    // The lease is fed by the relay alone (the page sends nothing): well past the 500 ms watchdog.
    const before = sent.outputs;
    await eventually(() => sent.outputs >= before + 10, 5000, 'heartbeats');
    expect(gw.hub.status()).toMatchObject({ armed: true, watchdog: { state: 'fed' } });

    // The program stops running (a fault, a breakpoint, Pause): the relay tells the gateway stop at once.
    relay.frame(frame('faulted'));
    await eventually(async () => (await coil(1)) === 0, 5000, 'safe state');
    expect(gw.hub.status().disarm?.cause).toBe('stop');
    await eventually(() => ended.length === 1, 3000, 'drive ended reported');
    expect(ended[0]).toMatch(/faulted/);
    detach();
    client.disconnect();
    await eventually(() => !gw.hub.status().controller, 5000, 'lease released');
  });

  it('the page-side bridge coalesces a 1 kHz output stream the same way and never drops the last image', async () => {
    const sent = { outputs: 0 };
    const client = new GatewayClient({ socketUrl: `ws://127.0.0.1:${gw.port}/io`, token: gw.token, role: 'controller', socketFactory: countingFactory(sent) });
    client.connect();
    await eventually(() => client.snapshot.link === 'open' && client.snapshot.status !== null, 5000, 'open');
    const bridge = new GatewayBridge(client);
    bridge.arm();
    await eventually(() => client.snapshot.status?.armed === true, 5000, 'armed');
    let scans = 0;
    const t0 = Date.now();
    await new Promise<void>((done) => {
      const timer = setInterval(() => {
        scans++;
        // Ends with Q FALSE and %QX0.4 TRUE, set only by the very last scan.
        bridge.sendOutputs({ '%QX0.1': scans % 2 === 1, '%QX0.4': false });
        if (Date.now() - t0 >= 2000) {
          clearInterval(timer);
          bridge.sendOutputs({ '%QX0.1': false, '%QX0.4': true });
          done();
        }
      }, 1);
    });
    const elapsed = Date.now() - t0;
    const sentInBurst = sent.outputs;
    await eventually(async () => (await coil(4)) === 1 && (await coil(1)) === 0, 5000, 'the last image on the device');
    expect(sentInBurst).toBeLessThanOrEqual(Math.ceil(elapsed / 50) + 2);
    expect(client.snapshot.lastError).toBeNull();
    bridge.stop();
    await eventually(async () => (await coil(4)) === 0, 5000, 'safe state');
    client.disconnect();
  });

  it('an online change that moves an output to another address switches the old one off; it is not left ON with no program writing it', async () => {
    const { relay, transport } = relayInWorker((url) => new WebSocket(url) as unknown as SocketLike, {
      setInputs: () => undefined,
      wantOutputs: () => undefined,
    });
    const client = new GatewayClient({ socketUrl: `ws://127.0.0.1:${gw.port}/io`, token: gw.token, role: 'controller', socketFactory: workerSocketFactory(transport) });
    client.connect();
    await eventually(() => client.snapshot.link === 'open' && client.snapshot.status !== null, 5000, 'open through the relay');
    const bridge = new GatewayBridge(client, workerDriver(transport));
    transport.send({ type: 'gwPrograms', ids: ['P'] });
    bridge.requestArm();
    const { bindings } = checkBindings(project, client.snapshot.points);
    const detach = bridge.attach({ setInputs: () => undefined, onOutputs: () => () => undefined }, bindings);
    relay.frame(frame('running'));
    await eventually(() => client.snapshot.status?.armed === true, 5000, 'armed');
    relay.outputs({ '%QX0.1': true }, 'P');
    await eventually(async () => (await coil(1)) === 1, 5000, 'Q ON at %QX0.1');

    // Applied online: Q now at %QX0.5 (the page tells the worker the program shown changed).
    transport.send({ type: 'gwPrograms', ids: ['P2'] });
    await new Promise((r) => queueMicrotask(() => r(undefined)));
    relay.outputs({ '%QX0.5': true }, 'P2');
    await eventually(async () => (await coil(5)) === 1, 5000, 'Q ON at its new address');
    await eventually(async () => (await coil(1)) === 0, 5000, 'the old address switched off');
    // The heartbeat keeps it off, and the gateway stays armed for the program's own output.
    relay.outputs({ '%QX0.5': true }, 'P2');
    expect(gw.hub.status().armed).toBe(true);
    expect(await coil(1)).toBe(0);

    relay.frame(frame('paused'));
    await eventually(async () => (await coil(5)) === 0, 5000, 'safe state');
    detach();
    client.disconnect();
    await eventually(() => !gw.hub.status().controller, 5000, 'lease released');
  });
});
