// The config file: OpenPLC default map, explicit ranges, and clear located errors.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { loadConfigFile, resolveConfig } from '../../src/gateway/config';
import { planBlocks } from '../../src/gateway/modbusPlan';

const device = (points: unknown[], extra: Record<string, unknown> = {}) => ({ devices: [{ id: 'io1', host: '127.0.0.1', points, ...extra }] });

describe('gateway config', () => {
  it('has safe defaults: watchdog 1000 ms, no auto re-arm, simulated device when no devices are named', () => {
    const c = resolveConfig({});
    expect(c).toMatchObject({ watchdogMs: 1000, autoRearm: false, devices: [], simulated: { modbusPort: 5020 } });
  });

  it('maps addresses to Modbus tables with the OpenPLC default map, bit address = byte x 8 + bit', () => {
    const c = resolveConfig(device([{ address: '%IX2.3', count: 2 }, { address: '%QX0.7', count: 2, hold: true }, { address: '%IW5' }, { address: '%QW10', type: 'INT' }]));
    const d = c.devices[0];
    expect(d).toMatchObject({ port: 502, unitId: 1, pollMs: 100, timeoutMs: 1000 });
    expect(d?.resolvedPoints.map((p) => `${p.address}=${p.table}:${p.register}${p.hold ? ' hold' : ''}`)).toEqual([
      '%IX2.3=discreteInputs:19',
      '%IX2.4=discreteInputs:20',
      '%QX0.7=coils:7 hold',
      '%QX1.0=coils:8 hold',
      '%IW5=inputRegisters:5',
      '%QW10=holdingRegisters:10',
    ]);
  });

  it('maps any range with an explicit table and register', () => {
    const c = resolveConfig(device([{ address: '%IX0.0', count: 3, table: 'coils', register: 100 }, { address: '%IW0', count: 2, table: 'holdingRegisters', register: 4000 }]));
    const blocks = planBlocks(c.devices[0]?.resolvedPoints ?? [], false);
    expect(blocks.map((b) => `${b.table}@${b.start}x${b.points.length}`)).toEqual(['coils@100x3', 'holdingRegisters@4000x2']);
  });

  it.each([
    [{ watchdogMs: 100 }, 'watchdogMs'],
    [{ watchdogMs: 9000 }, 'watchdogMs'],
    [{ token: 'short' }, 'token: a fixed token needs at least 16 characters'],
    [{ devices: [{ id: 'x', host: '127.0.0.1', points: [{ address: '%IX0.0' }], pollMs: 'fast' }] }, 'devices[0].pollMs'],
    [{ bogus: 1 }, 'bogus'],
    [device([{ address: '%MW3' }]), 'devices[0].points[0]: "%MW3" is not an I/O address'],
    [device([{ address: '%QX0.0', table: 'discreteInputs' }]), 'cannot use Modbus discreteInputs; use coils'],
    [device([{ address: '%IX0.0', hold: true }]), '"hold" applies to outputs only'],
    [device([{ address: '%IW0', type: 'BOOL' }]), 'is a word address and cannot have type BOOL'],
    [device([{ address: '%IX120.0' }]), 'outside the OpenPLC default map; give "table" and "register"'],
    [device([{ address: '%QX0.0', count: 2 }, { address: '%QX0.1' }]), 'devices[0].points[1]: %QX0.1 is mapped twice'],
    [device([{ address: '%QX0.0' }, { address: '%QX5.0', table: 'coils', register: 0 }]), '%QX5.0 and %QX0.0 both write coils 0'],
    [{ devices: [{ id: 'a', host: '127.0.0.1', points: [{ address: '%IX0.0' }] }, { id: 'b', host: '127.0.0.1', points: [{ address: '%IX0.0' }] }] }, '%IX0.0 is already mapped on device "a"'],
  ])('refuses %j with a located message', (raw, text) => {
    expect(() => resolveConfig(raw, 'gw.json')).toThrow(text);
  });

  it('names the file when it is not JSON', () => {
    const dir = mkdtempSync(join(tmpdir(), 'rungsmith-cfg-'));
    const file = join(dir, 'bad.json');
    writeFileSync(file, '{ "devices": [ }');
    expect(() => loadConfigFile(file)).toThrow(`${file}: not valid JSON`);
  });
});
