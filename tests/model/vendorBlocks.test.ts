// OpenPLC's vendor library blocks and a file's unknown blocks as external blocks: the library
// resolves them with their interfaces, so programs that call MQTT, sockets or board I/O still run.
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { blockSignature } from '../../src/model/blocks';
import { boxLayout } from '../../src/model/boxLayout';
import { externalBlockPou, externalInfo } from '../../src/model/externalBlocks';
import { newPou, newProject, variable } from '../../src/model/factory';
import { blockLibrary, declaredPinType, isInOutPin, STANDARD_LIBRARY } from '../../src/model/library';
import { loadProject, saveProject } from '../../src/model/load';
import type { ExternalBlock } from '../../src/model/project';
import { VENDOR_BLOCKS, VENDOR_LIBRARIES, vendorBlock } from '../../src/model/vendorBlocks';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { ladder, plcOf, project as ladderProject, vars } from '../engine/ladder';
import { expectVendorCallsKnown, foreignCalls, pinNames } from './vendorCalls';

const root = fileURLToPath(new URL('../..', import.meta.url));
/** PLCopen files of the repository: hand-written ones, and MIT-licensed corpus files in corpus/. */
const FIXTURES = [join(root, 'tests', 'fixtures', 'plcopen'), join(root, 'tests', 'fixtures', 'plcopen', 'corpus')];

const fixtureFile = (file: string): string => {
  const path = FIXTURES.map((dir) => join(dir, file)).find((p) => existsSync(p));
  if (!path) throw new Error(`${file} is missing from ${FIXTURES.join(' and ')}`);
  return readFileSync(path, 'utf8');
};

describe('OpenPLC vendor blocks', () => {
  test('vendor-calls.xml: every block it calls from an OpenPLC library (MQTT, Communication, P1AM) is known, with every pin it wires', () => {
    expectVendorCallsKnown(fixtureFile('vendor-calls.xml'), [
      ...['MQTT_CONNECT', 'MQTT_RECEIVE', 'MQTT_SEND', 'MQTT_SUBSCRIBE'],
      ...['P1AM_INIT', 'P1_16CDR'],
      ...['TCP_CONNECT', 'TCP_RECEIVE', 'TCP_SEND'],
    ]);
  });

  test('vendor-calls.xml imports: each call is an instance of the vendor block, and the programs compile', () => {
    const r = importPlcopen(fixtureFile('vendor-calls.xml'));
    expect(r.ok).toBe(true);
    if (!r.ok) return;
    expect(r.project.pous.map((p) => p.name)).toEqual(['MqttLink', 'TcpLink', 'Board']);
    const board = r.project.pous.find((p) => p.name === 'Board')!;
    expect(board.variables.map((v) => `${v.name}: ${v.type}`)).toEqual(['Bus0: P1AM_INIT', 'Slot1: P1_16CDR']);
    const { program, diagnostics } = compileProgram(r.project, { pou: 'TcpLink' });
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    expect(createPlc(program!, { cycleMs: 20 }).scans(3).fault).toBeUndefined();
  });

  test('sakunamary i2c_test: blocks no shipped library defines become external blocks with the pins the file wires', () => {
    // I2C_AHT20 and I2C_OLED come from a fork's library; REAL_TO_STRING is a standard conversion.
    const calls = foreignCalls(fixtureFile('sakunamary__i2c_test.xml'));
    expect(calls.map((c) => c.typeName).sort()).toEqual(['I2C_AHT20', 'I2C_OLED']);
    expect(vendorBlock('I2C_AHT20')).toBeUndefined();
    const externalBlocks: ExternalBlock[] = calls.map((c) => ({
      name: c.typeName,
      kind: c.instance ? 'FUNCTION_BLOCK' : 'FUNCTION',
      pins: c.pins,
    }));
    const project = newProject('P', { externalBlocks });
    const lib = blockLibrary(project);
    const aht = lib.signature('I2C_AHT20')!;
    expect(pinNames(aht.inputs)).toEqual(['SCK_PIN', 'SDA_PIN']);
    expect(pinNames(aht.outputs)).toEqual(['TEMP', 'RH']);
    expect(aht.outputs.map(declaredPinType)).toEqual(['ANY', 'ANY']);
    expect(pinNames(lib.signature('I2C_OLED')!.inputs)).toEqual(['LINE1', 'LINE2', 'LINE3', 'LINE4']);
    expect(lib.isExternal('i2c_oled')).toBe(true);
    expect(externalInfo(lib.userPou('I2C_OLED'))).toEqual({ origin: 'project' });
    expect(lib.isExternal('REAL_TO_STRING')).toBe(false);
    expect(lib.signature('REAL_TO_STRING')!.category).toBe('conversion');
    // The OpenPLC library's own I2C block is still there.
    expect(lib.signature('I2C_THREMO_4_OUT')?.outputs.length).toBe(4);
  });

  test('an MQTT block: its interface as OpenPLC declares it, STRING pins typed STRING', () => {
    const lib = blockLibrary(newProject('P'));
    const send = lib.signature('mqtt_send')!;
    expect(send.inputs.map((p) => `${p.name}:${declaredPinType(p)}:${p.type}`)).toEqual([
      'SEND:BOOL:BOOL',
      'TOPIC:STRING:STRING',
      'MESSAGE:STRING:STRING',
    ]);
    expect(send.outputs.map((p) => `${p.name}:${p.type}`)).toEqual(['SUCCESS:BOOL']);
    expect(send.description).toMatch(/^Publishes MESSAGE to TOPIC/);
    expect(send.description).toContain('External block (OpenPLC MQTT library)');
    expect(send.description).toContain('outputs hold their initial values');
    expect(send.description).not.toContain('show as ANY');
    expect(lib.signature('P1_08N')!.description).not.toContain('ANY');
    // Drawn like any FB: power flow through SEND and SUCCESS, or EN/ENO on request.
    expect(boxLayout({ blockType: 'MQTT_SEND' }, lib)!.inputs.map((p) => p.name)).toEqual(['SEND', 'TOPIC', 'MESSAGE']);
    expect(boxLayout({ blockType: 'MQTT_SEND', executionControl: true }, lib)!.outputs.map((p) => p.name)).toEqual(['ENO', 'SUCCESS']);
  });

  test('the POU behind a vendor block: interface, no networks, marked external, never a POU of the project', () => {
    const project = newProject('P');
    const lib = blockLibrary(project);
    const pou = lib.userPou('TCP_RECEIVE')!;
    expect(pou).toMatchObject({ name: 'TCP_RECEIVE', kind: 'FUNCTION_BLOCK', language: 'LD', networks: [] });
    expect(pou.variables.map((v) => `${v.varClass} ${v.name}: ${v.type}`)).toEqual([
      'input RECEIVE: BOOL',
      'input SOCKET_ID: INT',
      'output BYTES_RECEIVED: INT',
      'output MSG: STRING',
    ]);
    expect(pou.variables.every((v) => v.initial === undefined && !v.retain)).toBe(true);
    expect(externalInfo(pou)).toEqual({ origin: 'vendor', library: 'Communication', vendor: 'OpenPLC' });
    expect(lib.isFbType('TCP_RECEIVE')).toBe(true);
    expect(project.pous.map((p) => p.name)).toEqual(['Main']);
    expect(lib.userBlocks).toEqual([]);
    expect(externalInfo(project.pous[0])).toBeUndefined();
  });

  test('the shipped libraries: unique names, none hides a standard block, pins listed in declaration order', () => {
    expect(VENDOR_LIBRARIES.map((l) => l.name)).toEqual([
      'Communication',
      'MQTT',
      'P1AM',
      'Arduino',
      'I2C sensors',
      'Jaguar',
      'SL-RP4',
      'Sequent Microsystems cards',
      'STM32 CAN',
    ]);
    const names = VENDOR_BLOCKS.map((b) => b.name.toUpperCase());
    expect(new Set(names).size).toBe(names.length);
    expect(names.filter((n) => blockSignature(n))).toEqual([]);
    for (const b of VENDOR_BLOCKS) {
      const pins = b.pins.map((p) => p.name.toUpperCase());
      expect(new Set(pins).size, b.name).toBe(pins.length);
      expect(b.comment, b.name).toMatch(/\.$/);
    }
    const card = vendorBlock('SM_BAS')!;
    expect(card.pins.filter((p) => p.dir === 'in').map((p) => p.name)).toEqual([
      'STACK',
      ...['TRIAC1', 'TRIAC2', 'TRIAC3', 'TRIAC4', 'LED1', 'LED2', 'LED3', 'LED4'],
      ...['IN1_T', 'IN2_T', 'IN3_T', 'IN4_T', 'IN5_T', 'IN6_T', 'IN7_T', 'IN8_T'],
      ...['Q0_10V1', 'Q0_10V2', 'Q0_10V3', 'Q0_10V4'],
    ]);
    expect(vendorBlock('p1_16n')!.pins.filter((p) => p.dir === 'out')).toHaveLength(16);
    expect(vendorBlock('P1_08T')!.pins.every((p) => p.dir === 'in')).toBe(true);
    // The palette's "Vendor (external)" group: every shipped block, library by library.
    expect(blockLibrary(newProject('P')).externalBlocks.map((s) => s.name)).toEqual(VENDOR_BLOCKS.map((b) => b.name));
  });
});

describe('a program calling a vendor block runs', () => {
  test('the block does nothing: inputs are stored, outputs hold their initial values until the watch table sets them', () => {
    // [Go]--[ROTARY_SWITCH R1: READ -> ERROR, OUT -> Pos]--(Err)
    const p = ladderProject(vars('Go BOOL', 'Err BOOL', 'Pos INT', 'R1 ROTARY_SWITCH'), [
      ladder(['[Go] # # (Err)', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'ROTARY_SWITCH', instance: 'R1', outputs: { OUT: 'Pos' } }] }),
    ]);
    const plc = plcOf(p);
    expect(plc.variableNames()).toEqual(['Go', 'Err', 'Pos', 'R1.READ', 'R1.ERROR', 'R1.OUT']);
    plc.write('Go', true);
    plc.scan();
    expect([plc.read('R1.READ'), plc.read('Err'), plc.read('Pos')]).toEqual([true, false, 0]);
    plc.write('R1.OUT', 7);
    plc.force('R1.ERROR', true);
    plc.scans(2);
    expect([plc.read('Err'), plc.read('Pos')]).toEqual([true, 7]);
  });
});

describe('which definition a name resolves to', () => {
  const ownSend = newPou('MQTT_Send', {
    kind: 'FUNCTION_BLOCK',
    variables: [variable('Go', 'BOOL', { varClass: 'input' }), variable('Done', 'BOOL', { varClass: 'output' })],
  });

  test("the project's own POU wins over a vendor block of the same name", () => {
    const lib = blockLibrary(newProject('P', { pous: [newPou('Main'), ownSend] }));
    expect(lib.isExternal('MQTT_SEND')).toBe(false);
    expect(lib.userPou('MQTT_SEND')).toBe(ownSend);
    expect(pinNames(lib.signature('MQTT_SEND')!.inputs)).toEqual(['Go']);
    expect(lib.signature('MQTT_SEND')!.category).toBe('user');
    expect(lib.externalBlocks.map((s) => s.name)).not.toContain('MQTT_SEND');
    expect(lib.isExternal('MQTT_CONNECT')).toBe(true);
  });

  test("the project's external block (the file's pins) wins over the vendor block; its own POU over both", () => {
    const fileSend: ExternalBlock = { name: 'MQTT_SEND', kind: 'FUNCTION_BLOCK', pins: [{ name: 'SEND', dir: 'in', type: 'BOOL' }] };
    const lib = blockLibrary(newProject('P', { externalBlocks: [fileSend] }));
    expect(pinNames(lib.signature('MQTT_SEND')!.inputs)).toEqual(['SEND']);
    expect(externalInfo(lib.userPou('MQTT_SEND'))?.origin).toBe('project');
    expect(lib.externalBlocks.filter((s) => s.name === 'MQTT_SEND')).toHaveLength(1);
    const both = blockLibrary(newProject('P', { pous: [newPou('Main'), ownSend], externalBlocks: [fileSend] }));
    expect(both.userPou('MQTT_SEND')).toBe(ownSend);
  });

  test('a standard block wins over a POU and an external block of the same name', () => {
    const ton = newPou('TON', { kind: 'FUNCTION_BLOCK', variables: [variable('X', 'BOOL', { varClass: 'input' })] });
    const lib = blockLibrary(
      newProject('P', {
        pous: [newPou('Main'), ton],
        externalBlocks: [{ name: 'ton', kind: 'FUNCTION_BLOCK', pins: [{ name: 'Y', dir: 'in' }] }],
      }),
    );
    expect(lib.signature('TON')).toBe(blockSignature('TON'));
    expect(lib.userPou('TON')).toBeUndefined();
    expect(lib.isExternal('TON')).toBe(false);
    expect(lib.externalBlocks.map((s) => s.name)).not.toContain('ton');
  });

  test('the standard library alone knows no vendor blocks', () => {
    expect(STANDARD_LIBRARY.signature('MQTT_SEND')).toBeUndefined();
    expect(STANDARD_LIBRARY.isExternal('MQTT_SEND')).toBe(false);
    expect(STANDARD_LIBRARY.externalBlocks).toEqual([]);
  });

  test('memoised on the POU list and the external block list; a new list gives a new library', () => {
    const externalBlocks: ExternalBlock[] = [{ name: 'Gadget', kind: 'FUNCTION_BLOCK', pins: [] }];
    const project = newProject('P', { externalBlocks });
    expect(blockLibrary(project)).toBe(blockLibrary({ pous: project.pous, externalBlocks }));
    const edited = { ...project, externalBlocks: [...externalBlocks, { name: 'Widget', kind: 'FUNCTION_BLOCK' as const, pins: [] }] };
    expect(blockLibrary(edited).isExternal('Widget')).toBe(true);
    expect(blockLibrary(project).isExternal('Widget')).toBe(false);
  });
});

describe('externalBlockPou', () => {
  test('a function: OUT is its result, EN/ENO dropped, a pin without a type is ANY', () => {
    const pou = externalBlockPou({
      name: 'STR_FMT',
      kind: 'FUNCTION',
      pins: [
        { name: 'EN', dir: 'in', type: 'BOOL' },
        { name: 'IN', dir: 'in', type: 'REAL' },
        { name: 'Digits', dir: 'in' },
        { name: 'ENO', dir: 'out', type: 'BOOL' },
        { name: 'OUT', dir: 'out', type: 'STRING' },
        { name: 'Buf', dir: 'inOut', type: 'INT', initial: '3' },
      ],
    });
    expect(pou.kind).toBe('FUNCTION');
    expect(pou.returnType).toBe('STRING');
    expect(pou.variables.map((v) => `${v.varClass} ${v.name}: ${v.type}${v.initial ? ` := ${v.initial}` : ''}`)).toEqual([
      'input IN: REAL',
      'input Digits: ANY',
      'inOut Buf: INT := 3',
    ]);
    const lib = blockLibrary(newProject('P', { externalBlocks: [{ name: 'STR_FMT', kind: 'FUNCTION', pins: [{ name: 'IN', dir: 'in', type: 'REAL' }] }] }));
    const sig = lib.signature('STR_FMT')!;
    expect(sig.kind).toBe('function');
    expect(sig.outputs.map((p) => `${p.name}:${p.type}`)).toEqual(['OUT:BOOL']);
    expect(isInOutPin(sig.inputs[0]!)).toBe(false);
    expect(lib.isFbType('STR_FMT')).toBe(false);
  });

  test("a FUNCTION's declared returnType wins over its OUT pin", () => {
    const pou = externalBlockPou({ name: 'F', kind: 'FUNCTION', returnType: 'INT', pins: [{ name: 'OUT', dir: 'out', type: 'REAL' }] });
    expect(pou.returnType).toBe('INT');
    expect(pou.variables).toEqual([]);
  });
});

describe('Project.externalBlocks in the project file', () => {
  const externalBlocks: ExternalBlock[] = [
    {
      name: 'I2C_AHT20',
      kind: 'FUNCTION_BLOCK',
      pins: [
        { name: 'SCK_PIN', dir: 'in', type: 'INT' },
        { name: 'TEMP', dir: 'out', type: 'REAL', initial: '20.0' },
      ],
      library: 'I2C sensors (fork)',
      comment: 'AHT20 temperature and humidity sensor.',
    },
    { name: 'Fmt', kind: 'FUNCTION', returnType: 'INT', pins: [{ name: 'X', dir: 'inOut' }] },
  ];

  test('save and load keep them unchanged, and the loaded project resolves them', () => {
    const project = newProject('P', { externalBlocks });
    const loaded = loadProject(saveProject(project));
    expect(loaded.ok).toBe(true);
    if (!loaded.ok) return;
    expect(loaded.project.externalBlocks).toEqual(externalBlocks);
    expect(loaded.project).toEqual(project);
    expect(blockLibrary(loaded.project).signature('I2C_AHT20')!.outputs[0]).toMatchObject({ name: 'TEMP', type: 'REAL' });
    const plain = newProject('P');
    expect(saveProject(plain)).not.toContain('externalBlocks');
  });

  test('a bad external block is refused with its path', () => {
    const bad = (blocks: unknown) => {
      const r = loadProject(JSON.stringify({ ...newProject('P'), externalBlocks: blocks }));
      return r.ok ? [] : r.errors.map((e) => `${e.path}: ${e.message}`);
    };
    expect(bad([{ name: 'A', kind: 'FUNCTION_BLOCK', pins: [{ name: 'X', dir: 'sideways' }] }])[0]).toMatch(/^externalBlocks\[0\]\.pins\[0\]\.dir/);
    expect(bad([{ name: 'A', kind: 'PROGRAM', pins: [] }])[0]).toMatch(/^externalBlocks\[0\]\.kind/);
    expect(bad([externalBlocks[0], { ...externalBlocks[0], name: 'i2c_aht20' }])).toEqual([
      'externalBlocks[1].name: duplicate external block "i2c_aht20"',
    ]);
    expect(bad([{ name: 'A', kind: 'FUNCTION_BLOCK', pins: [{ name: 'X', dir: 'in' }, { name: 'x', dir: 'out' }] }])).toEqual([
      'externalBlocks[0].pins[1].name: external block "A" has the pin "x" twice',
    ]);
  });
});
