// What the Hardware panel and the canvas say about field I/O: why Arm is unavailable, which inputs come
// from the device, and the "device: FALSE" marker drawn next to a coil whose device output differs.
import { describe, expect, test } from 'vitest';
import { IDLE_VIEW, type GatewayView } from '../../src/bridge/GatewayClient';
import { armBlocker } from '../../src/editor/hardware/armState';
import { deviceMarks } from '../../src/editor/hardware/deviceMarks';
import { fieldInputAddress } from '../../src/editor/hardware/fieldIo';
import type { Network } from '../../src/model/project';
import type { SimState } from '../../src/store/simState';
import { motorNetwork } from '../sim/programs';

const status = (state: 'online' | 'offline', armed = false): GatewayView['status'] => ({
  v: 1,
  t: 'status',
  devices: [{ id: 'io1', state, error: state === 'offline' ? 'connection refused' : null, outputs: armed ? 'driven' : 'safe' }],
  armed,
  disarm: armed ? null : { cause: 'device-lost', message: 'device "io1" lost its connection', at: 0 },
  watchdog: { ms: 1000, state: 'idle', autoRearm: false },
  controller: true,
});

const view = (over: Partial<GatewayView>): GatewayView => ({
  ...IDLE_VIEW,
  link: 'open',
  role: 'controller',
  points: [
    { address: '%IX0.0', type: 'BOOL', dir: 'in', device: 'io1' },
    { address: '%QX0.0', type: 'BOOL', dir: 'out', device: 'io1' },
  ],
  ...over,
});

const variables = [
  { name: 'Start', type: 'BOOL', location: '%IX0.0', role: 'input' as const },
  { name: 'Stop', type: 'BOOL', location: '%IX0.1', role: 'input' as const },
  { name: 'Motor', type: 'BOOL', location: '%QX0.0', role: 'output' as const },
];

function simState(values: boolean[]): SimState {
  return {
    live: true,
    layout: { variables },
    variableIndex: new Map(variables.map((v, i) => [v.name.toUpperCase(), i])),
    values,
  } as unknown as SimState;
}

describe('field I/O in the editor', () => {
  test('Arm is unavailable, with the reason, while a device is not online or this page is not the controller', () => {
    expect(armBlocker(view({ status: status('offline') }))).toBe('device "io1" is offline: arm when it is online');
    expect(armBlocker(view({ status: status('online'), role: 'observer' }))).toBe('only the controller can arm');
    expect(armBlocker(view({ status: status('online') }))).toBeNull();
  });

  test('an input comes from the device only when hardware is attached as controller and the gateway has the point', () => {
    expect(fieldInputAddress(variables[0], view({}))).toBe('%IX0.0');
    expect(fieldInputAddress(variables[1], view({}))).toBeUndefined(); // no such point on the gateway
    expect(fieldInputAddress(variables[0], view({ role: 'observer' }))).toBeUndefined();
    expect(fieldInputAddress(variables[2], view({}))).toBeUndefined(); // an output
  });

  test('the canvas marks the Motor coil and contact "device: FALSE" while the device holds the safe state', () => {
    const network: Network = motorNetwork();
    const motorElements = network.elements.filter((e) => (e.kind === 'coil' || e.kind === 'contact') && e.variable === 'Motor').map((e) => e.id);
    const marks = deviceMarks(simState([false, false, true]), network, view({ values: { '%QX0.0': false } }));
    expect(marks).toEqual(motorElements.map((id) => [id, 'device: FALSE']));
    expect(deviceMarks(simState([false, false, true]), network, view({ values: { '%QX0.0': true } }))).toEqual([]);
    expect(deviceMarks(simState([false, false, true]), network, { ...view({ values: { '%QX0.0': false } }), link: 'idle' })).toEqual([]);
  });

  test('an input that changed on the device while the program is paused shows the device value next to the stale one', () => {
    const network: Network = motorNetwork();
    const startElements = network.elements.filter((e) => e.kind === 'contact' && e.variable === 'Start').map((e) => e.id);
    const paused = { ...simState([false, false, false]), mode: 'paused' } as SimState;
    const device = view({ values: { '%IX0.0': true, '%QX0.0': false } });
    expect(deviceMarks(paused, network, device)).toEqual(startElements.map((id) => [id, 'device: TRUE']));
    // Running as controller the program reads it every scan: nothing stale to mark.
    expect(deviceMarks({ ...paused, mode: 'running' } as SimState, network, device)).toEqual([]);
    // Running as an observer the program does not read the device: the difference is shown.
    expect(deviceMarks({ ...paused, mode: 'running' } as SimState, network, { ...device, role: 'observer' })).toEqual(startElements.map((id) => [id, 'device: TRUE']));
    expect(deviceMarks({ ...simState([true, false, false]), mode: 'paused' } as SimState, network, device)).toEqual([]);
  });
});
