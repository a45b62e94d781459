// The built-in simulated device, checked from outside with Debian's mbpoll.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { resolveConfig } from '../../src/gateway/config';
import { startGateway, type RunningGateway } from '../../src/gateway/gateway';
import { eventually, mbpoll, mbpollValues, TestClient } from './helpers';

describe('simulated I/O device', () => {
  let gw: RunningGateway;
  let simPort: number;
  beforeAll(async () => {
    gw = await startGateway({ port: 0, config: resolveConfig({ simulated: { modbusPort: 0 } }), distDir: null });
    simPort = gw.simulated?.modbusServerPort ?? 0;
  });
  afterAll(() => gw?.close());

  it('offers 16 DI, 16 DO, 4 AI and 4 AO on the OpenPLC default map', async () => {
    const c = await TestClient.hello(gw.port, gw.token, 'observer');
    const welcome = c.messages.find((m) => m.t === 'welcome');
    const points = welcome?.t === 'welcome' ? welcome.points : [];
    const count = (dir: string, type: string) => points.filter((p) => p.dir === dir && (p.type === 'BOOL') === (type === 'BOOL')).length;
    expect([count('in', 'BOOL'), count('out', 'BOOL'), count('in', 'WORD'), count('out', 'WORD')]).toEqual([16, 16, 4, 4]);
    expect(points.map((p) => p.address)).toContain('%IX1.7');
    expect(points.map((p) => p.address)).toContain('%QW3');
    expect(welcome).toMatchObject({ devices: [{ id: 'sim', kind: 'simulated' }] });
    c.close();
  });

  it('sets inputs from a client and shows them to mbpoll as discrete inputs and input registers', async () => {
    const c = await TestClient.hello(gw.port, gw.token, 'observer');
    c.send({ t: 'simulate', seq: 1, values: { '%IX0.1': true, '%IX1.0': true, '%IW2': 1234 } });
    await eventually(() => c.values()['%IX1.0'] === true, 3000, 'input echoed');
    expect(mbpollValues(await mbpoll(simPort, ['-t', '1', '-r', '0', '-c', '10', '127.0.0.1']))).toEqual([0, 1, 0, 0, 0, 0, 0, 0, 1, 0]);
    expect(mbpollValues(await mbpoll(simPort, ['-t', '3', '-r', '0', '-c', '4', '127.0.0.1']))).toEqual([0, 0, 1234, 0]);
    c.close();
  });

  it('shows the controller outputs to mbpoll as coils and holding registers, and refuses outside writes to them', async () => {
    const c = await TestClient.armedController(gw.port, gw.token);
    c.send({ t: 'outputs', seq: 1, values: { '%QX0.0': true, '%QX0.3': true, '%QW1': 777 } });
    await eventually(() => c.values()['%QX0.3'] === true, 3000, 'written');
    expect(mbpollValues(await mbpoll(simPort, ['-t', '0', '-r', '0', '-c', '4', '127.0.0.1']))).toEqual([1, 0, 0, 1]);
    expect(mbpollValues(await mbpoll(simPort, ['-t', '4', '-r', '0', '-c', '2', '127.0.0.1']))).toEqual([0, 777]);
    await expect(mbpoll(simPort, ['-t', '0', '-r', '0', '127.0.0.1', '0'])).rejects.toThrow(/Illegal function/);
    c.send({ t: 'stop' });
    await eventually(() => c.values()['%QX0.3'] === false, 3000, 'safe state');
    c.close();
  });

  it('lets a plant simulator drive the inputs through coils 800+ and holding registers 2048+', async () => {
    const c = await TestClient.hello(gw.port, gw.token, 'observer');
    await mbpoll(simPort, ['-t', '0', '-r', '805', '127.0.0.1', '1']);
    await mbpoll(simPort, ['-t', '4', '-r', '2051', '127.0.0.1', '65535']);
    await eventually(() => c.values()['%IX0.5'] === true && c.values()['%IW3'] === 65535, 3000, 'inputs driven over Modbus');
    expect(c.quality()['%IX0.5']).toBe('good');
    c.close();
  });
});
