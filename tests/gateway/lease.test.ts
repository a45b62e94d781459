// The controller lease on the simulated device: opt-in auto re-arm, and a trip survives a reconnect.
import { afterEach, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { eventually, TestClient } from './helpers';

describe('controller lease', () => {
  let gw: RunningGateway | undefined;
  afterEach(() => gw?.close());

  it('with autoRearm, new outputs after a watchdog trip resume without "arm"', async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ watchdogMs: 200, autoRearm: true, simulated: { modbusPort: null } }), distDir: null });
    const c = await TestClient.armedController(gw.port, gw.token);
    c.send({ t: 'outputs', seq: 1, values: { '%QX0.0': true } });
    await c.waitFor((m) => m.t === 'status' && m.watchdog.state === 'tripped' && !m.armed);
    expect(gw.simulated?.writtenValues().get('%QX0.0')).toBe(false);
    const before = c.messages.length;
    c.send({ t: 'outputs', seq: 2, values: { '%QX0.0': true } });
    await c.waitFor((m) => m.t === 'status' && m.armed && m.watchdog.state === 'fed', 3000, before);
    expect(gw.simulated?.writtenValues().get('%QX0.0')).toBe(true);
    expect(c.messages.slice(before).some((m) => m.t === 'error')).toBe(false);
    c.send({ t: 'stop' });
    c.close();
  });

  it('without autoRearm, a trip stays until a controller re-arms, even across reconnects', async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ watchdogMs: 200, simulated: { modbusPort: null } }), distDir: null });
    const first = await TestClient.armedController(gw.port, gw.token);
    first.send({ t: 'outputs', seq: 1, values: { '%QX0.1': true, '%QW0': 500 } });
    await first.waitFor((m) => m.t === 'status' && m.watchdog.state === 'tripped');
    expect(gw.simulated?.writtenValues().get('%QW0')).toBe(0);
    first.close();
    await first.waitClosed();
    await eventually(() => gw?.hub.status().controller === false, 3000, 'lease released');

    const second = await TestClient.hello(gw.port, gw.token, 'controller');
    expect(second.messages.find((m) => m.t === 'status')).toMatchObject({ armed: false, watchdog: { state: 'tripped' } });
    second.send({ t: 'outputs', seq: 1, values: { '%QX0.1': true } });
    expect(await second.waitFor((m) => m.t === 'error')).toMatchObject({ code: 'disarmed' });
    second.send({ t: 'arm' });
    second.send({ t: 'outputs', seq: 2, values: { '%QX0.1': true } });
    await eventually(() => gw?.simulated?.writtenValues().get('%QX0.1') === true, 3000, 'outputs after arm');
    second.send({ t: 'stop' });
    second.close();
  });
});
