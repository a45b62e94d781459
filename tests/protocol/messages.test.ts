// Protocol v1 schemas shared by the browser and the gateway.
import { describe, expect, it } from 'vitest';
import { clientMessageSchema, gatewayMessageSchema } from '../../src/protocol/messages';
import { canonicalAddress, valueFits } from '../../src/protocol/points';

describe('protocol v1 client messages', () => {
  it('accepts the messages of GATEWAY.md', () => {
    for (const m of [
      { v: 1, t: 'hello', token: 'abc', role: 'controller' },
      { v: 1, t: 'hello', token: 'abc', role: 'observer' },
      { v: 1, t: 'outputs', seq: 7, values: { '%QX0.0': true, '%QW1': 12 } },
      { v: 1, t: 'stop' },
      { v: 1, t: 'arm', seq: 3 },
      { v: 1, t: 'resync' },
      { v: 1, t: 'simulate', values: { '%IX0.1': false } },
    ]) {
      expect(clientMessageSchema.safeParse(m).success, JSON.stringify(m)).toBe(true);
    }
  });

  it('refuses other versions, unknown types, wrong field types and extra fields', () => {
    for (const m of [
      { v: 2, t: 'stop' },
      { t: 'stop' },
      { v: 1, t: 'reboot' },
      { v: 1, t: 'hello', role: 'controller' },
      { v: 1, t: 'hello', token: 'abc', role: 'admin' },
      { v: 1, t: 'outputs', seq: 1.5, values: {} },
      { v: 1, t: 'outputs', seq: 1, values: { '%QX0.0': 'on' } },
      { v: 1, t: 'outputs', seq: 1, values: { '%QX0.0': [true] } },
      { v: 1, t: 'stop', force: true },
    ]) {
      expect(clientMessageSchema.safeParse(m).success, JSON.stringify(m)).toBe(false);
    }
  });

  it('validates gateway messages the browser receives', () => {
    expect(
      gatewayMessageSchema.safeParse({
        v: 1,
        t: 'status',
        devices: [{ id: 'sim', state: 'online', error: null, outputs: 'driven' }],
        armed: true,
        disarm: null,
        watchdog: { ms: 1000, state: 'idle', autoRearm: false },
        controller: false,
      }).success,
    ).toBe(true);
    // A disarmed status says why; an unknown cause or outputs state is refused.
    const disarmed = {
      v: 1,
      t: 'status',
      devices: [{ id: 'plant', state: 'offline', error: 'ECONNREFUSED', outputs: 'safe-pending' }],
      armed: false,
      disarm: { cause: 'device-lost', message: 'device "plant" lost its connection', at: 1 },
      watchdog: { ms: 1000, state: 'idle', autoRearm: false },
      controller: true,
    };
    expect(gatewayMessageSchema.safeParse(disarmed).success).toBe(true);
    expect(gatewayMessageSchema.safeParse({ ...disarmed, disarm: { ...disarmed.disarm, cause: 'bored' } }).success).toBe(false);
    expect(gatewayMessageSchema.safeParse({ ...disarmed, devices: [{ ...disarmed.devices[0], outputs: 'maybe' }] }).success).toBe(false);
    expect(gatewayMessageSchema.safeParse({ v: 1, t: 'inputs', seq: 1, values: { '%IX0.0': true }, quality: { '%IX0.0': 'maybe' } }).success).toBe(false);
  });
});

describe('points', () => {
  it('writes addresses canonically and accepts only I/O bits and words', () => {
    expect(canonicalAddress('%ix0.3')).toBe('%IX0.3');
    expect(canonicalAddress('%QW02')).toBe('%QW2');
    expect(canonicalAddress('%MW3')).toBeUndefined();
    expect(canonicalAddress('%IX0.8')).toBeUndefined();
    expect(canonicalAddress('%ID0')).toBeUndefined();
  });

  it('checks values against the point type range', () => {
    expect(valueFits('BOOL', true)).toBe(true);
    expect(valueFits('BOOL', 1)).toBe(false);
    expect(valueFits('WORD', 65535)).toBe(true);
    expect(valueFits('WORD', 65536)).toBe(false);
    expect(valueFits('INT', -32768)).toBe(true);
    expect(valueFits('INT', 32768)).toBe(false);
    expect(valueFits('UINT', 1.5)).toBe(false);
  });
});
