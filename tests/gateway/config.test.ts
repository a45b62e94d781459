// The config file: OpenPLC default map, explicit ranges, and clear located errors.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { loadConfigFile, resolveConfig } from '../../src/gateway/config';
import { planBlocks } from '../../src/gateway/modbusPlan';

const device = (points: unknown[], extra: Record<string, unknown> = {}) => ({ devices: [{ id: 'io1', host: '127.0.0.1', points, ...extra }] });

describe('gateway config', () => {
  it('simulated.plant names a machine there is, and only for the simulated device (no "devices"): located errors', () => {
    expect(resolveConfig({ simulated: { plant: 'mixer' } }).simulated.plant).toBe('mixer');
    expect(() => resolveConfig({ simulated: { plant: 'tnak' } }, 'gw.json')).toThrow(
      'gw.json: simulated.plant: there is no machine "tnak"; the machines are tank,',
    );
    // Else the machine would silently not be there: real devices replace the simulated one.
    expect(() => resolveConfig({ ...device([{ address: '%IX0.0' }]), simulated: { plant: 'tank' } }, 'gw.json')).toThrow(
      'gw.json: simulated.plant: the machine "tank" is the built-in simulated device, which runs only with no "devices" configured',
    );
  });

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
    // Past the OpenPLC default map without an explicit table and register, also when a count runs past its end.
    [device([{ address: '%IX100.0' }]), 'devices[0].points[0]: %IX100.0 is outside the OpenPLC default map; give "table" and "register"'],
    [device([{ address: '%QX100.0' }]), 'devices[0].points[0]: %QX100.0 is outside the OpenPLC default map'],
    [device([{ address: '%IW1024' }]), 'devices[0].points[0]: %IW1024 is outside the OpenPLC default map'],
    [device([{ address: '%QW1024' }]), 'devices[0].points[0]: %QW1024 is outside the OpenPLC default map'],
    [device([{ address: '%QX0.0' }, { address: '%QX99.7', count: 2 }]), 'devices[0].points[1]: %QX100.0 (address 2 of 2 from %QX99.7) is outside the OpenPLC default map'],
    [device([{ address: '%IX99.0', count: 9 }]), 'devices[0].points[0]: %IX100.0 (address 9 of 9 from %IX99.0) is outside the OpenPLC default map'],
    [device([{ address: '%IW1020', count: 5 }]), '%IW1024 (address 5 of 5 from %IW1020) is outside the OpenPLC default map'],
    [device([{ address: '%QW1023', count: 2, table: 'holdingRegisters' }]), '%QW1024 (address 2 of 2 from %QW1023) is outside the OpenPLC default map'],
    [device([{ address: '%IX99.7', count: 2, register: 4000 }]), '%IX100.0 (address 2 of 2 from %IX99.7) is outside the OpenPLC default map'],
    // A device host is a bare host name or IP address; the port goes in "port".
    [device([{ address: '%IX0.0' }], { host: 'http://10.0.0.1' }), 'devices[0].host: "http://10.0.0.1" is a URL; give the bare host "10.0.0.1"'],
    [device([{ address: '%IX0.0' }], { host: 'tcp://127.0.0.1:502' }), 'devices[0].host: "tcp://127.0.0.1:502" is a URL; give the bare host "127.0.0.1" and the port in "port": 502'],
    [device([{ address: '%IX0.0' }], { host: '127.0.0.1:502' }), 'devices[0].host: "127.0.0.1:502" is a host with a port; give the bare host "127.0.0.1" and the port in "port": 502'],
    [device([{ address: '%IX0.0' }], { host: '[::1]:1502' }), 'give the bare host "::1" and the port in "port": 1502'],
    [device([{ address: '%IX0.0' }], { host: 'coupler 1' }), 'devices[0].host: "coupler 1" is not a host name or IP address'],
  ])('refuses %j with a located message', (raw, text) => {
    expect(() => resolveConfig(raw, 'gw.json')).toThrow(text);
  });

  it('accepts bare host names and IP addresses, and the end of the default map', () => {
    for (const host of ['127.0.0.1', 'localhost', '::1', 'coupler-1.plant.example', 'wago_750']) {
      expect(resolveConfig(device([{ address: '%IX0.0' }], { host })).devices[0]?.host, host).toBe(host);
    }
    const c = resolveConfig(device([{ address: '%IX99.6', count: 2 }, { address: '%QW1023' }, { address: '%IX120.0', count: 2, table: 'coils', register: 900 }]));
    expect(c.devices[0]?.resolvedPoints.map((p) => `${p.address}=${p.table}:${p.register}`)).toEqual([
      '%IX99.6=discreteInputs:798',
      '%IX99.7=discreteInputs:799',
      '%QW1023=holdingRegisters:1023',
      '%IX120.0=coils:900',
      '%IX120.1=coils:901',
    ]);
  });

  it.each([
    ['{\n  "watchdogMs": 500,\n  "watchdogMs": 2000\n}', 'watchdogMs: key "watchdogMs" appears twice in the same object (lines 2 and 3)'],
    [
      '{ "devices": [\n  { "id": "a", "host": "127.0.0.1", "points": [{ "address": "%IX0.0" }] },\n  { "id": "b",\n    "host": "127.0.0.1",\n    "points": [{ "address": "%QX0.0", "hold": false, "hold": true }] }\n] }',
      'devices[1].points[0].hold: key "hold" appears twice in the same object (lines 5 and 5)',
    ],
    ['{ "simulated": { "modbusPort": 5020 }, "devices": [], "simulated": { "modbusPort": null } }', 'simulated: key "simulated" appears twice'],
  ])('refuses a file in which a key appears twice: %s', (text, message) => {
    const dir = mkdtempSync(join(tmpdir(), 'rungsmith-cfg-'));
    const file = join(dir, 'gw.json');
    writeFileSync(file, text);
    expect(() => loadConfigFile(file)).toThrow(`${file}: ${message}`);
  });

  it('reads a file whose objects have distinct keys, even where the same key is in different objects', () => {
    const dir = mkdtempSync(join(tmpdir(), 'rungsmith-cfg-'));
    const file = join(dir, 'gw.json');
    writeFileSync(file, JSON.stringify({ devices: [{ id: 'a', host: '127.0.0.1', points: [{ address: '%IX0.0' }, { address: '%QX0.0', hold: true }] }] }, null, 2));
    expect(loadConfigFile(file).devices[0]?.resolvedPoints).toHaveLength(2);
  });

  it.each([
    ['{ "devices": [ }', 1, 16, 'a value expected at "}"'],
    ['{\n  "watchdogMs": 500\n  "autoRearm": true\n}', 3, 3, '"," expected at "\\"autoRearm\\""'],
    ['{\n  "watchdogMs": 500,\n}', 3, 1, 'a key in double quotes expected at "}"'],
    ['{\n  // comment\n  "watchdogMs": 500\n}', 2, 3, 'comments are not allowed in JSON'],
    ['{\n  "devices": [\n', 3, 1, 'at the end of the file'],
    ["{\n  'watchdogMs': 500\n}", 2, 3, 'unexpected character'],
  ])('a JSON syntax error names the line and column: %j', (text, line, column, words) => {
    const dir = mkdtempSync(join(tmpdir(), 'rungsmith-cfg-'));
    const file = join(dir, 'bad.json');
    writeFileSync(file, text);
    expect(() => loadConfigFile(file)).toThrow(`${file}:${line}:${column}: not valid JSON: `);
    expect(() => loadConfigFile(file)).toThrow(`(line ${line}, column ${column})`);
    expect(() => loadConfigFile(file)).toThrow(words);
  });

  it('accepts a file that starts with a UTF-8 byte order mark (as Windows editors save it)', () => {
    const dir = mkdtempSync(join(tmpdir(), 'rungsmith-cfg-'));
    const file = join(dir, 'bom.json');
    const json = JSON.stringify({ watchdogMs: 700, devices: [{ id: 'a', host: '127.0.0.1', points: [{ address: '%QX0.0' }] }] }, null, 2);
    writeFileSync(file, Buffer.concat([Buffer.from([0xef, 0xbb, 0xbf]), Buffer.from(json, 'utf8')]));
    const c = loadConfigFile(file);
    expect(c.watchdogMs).toBe(700);
    expect(c.devices[0]?.resolvedPoints.map((p) => p.address)).toEqual(['%QX0.0']);
  });

  it.each([
    ['999.1.1.1', '"999.1.1.1" is not an IPv4 address: 999 is above 255'],
    ['192.168.1.256', '"192.168.1.256" is not an IPv4 address: 256 is above 255'],
    ['10.0.1', '"10.0.1" is not an IPv4 address: it needs four numbers 0-255'],
    ['1.2.3.4.5', '"1.2.3.4.5" is not an IPv4 address'],
  ])('refuses the host %s at start, located at its key path', (host, words) => {
    const dir = mkdtempSync(join(tmpdir(), 'rungsmith-cfg-'));
    const file = join(dir, 'gw.json');
    writeFileSync(file, JSON.stringify({ devices: [{ id: 'a', host: '127.0.0.1', points: [{ address: '%IX0.0' }] }, { id: 'b', host, points: [{ address: '%QX0.0' }] }] }));
    expect(() => loadConfigFile(file)).toThrow(`${file}: invalid gateway config\n  devices[1].host: ${words}`);
  });

  it('names the file when it is not JSON', () => {
    const dir = mkdtempSync(join(tmpdir(), 'rungsmith-cfg-'));
    const file = join(dir, 'bad.json');
    writeFileSync(file, '{ "devices": [ }');
    expect(() => loadConfigFile(file)).toThrow(`${file}:1:16: not valid JSON`);
  });
});
