// CODESYS V3 exports (issue 23 class 8): the application's POUs and data types in the resource's
// addData, a CFC PLC_PRG kept but not run, a task naming its programs in `name`, BIT members of a
// structure, and blocks of CODESYS's Util library (BLINK and LIMITALARM run; RAMP_INT external).
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { fixture, imported } from './fixtures';
import { ldXml } from './ldXml';
import { pouCountText, pouToOpen } from '../../src/plcopen/importSummary';

const FILE = 'codesys-v3-application.xml';

describe('a CODESYS V3 application export', () => {
  test('imports its application POUs and data types, and says what each became', () => {
    const { project, report } = imported(FILE);
    expect(project.pous.map((p) => [p.name, p.kind, p.language])).toEqual([
      ['PLC_PRG', 'PROGRAM', 'FBD'],
      ['LampLogic', 'PROGRAM', 'LD'],
      ['BLINK', 'FUNCTION_BLOCK', 'ST'],
      ['LIMITALARM', 'FUNCTION_BLOCK', 'ST'],
    ]);
    expect(report.pous).toEqual([{ name: 'LampLogic', networks: expect.any(Number), from: 'POU body' }]);
    expect(project.dataTypes?.map((d) => d.name)).toEqual(['ST_Status']);
    // The task names its programs in `name` (typeName empty): both are kept.
    expect(project.tasks).toEqual([
      expect.objectContaining({
        name: 'MainTask',
        cycleMs: 10,
        programs: [
          { instance: 'PLC_PRG', pou: 'PLC_PRG' },
          { instance: 'LampLogic', pou: 'LampLogic' },
        ],
      }),
    ]);
    const text = report.warnings.map((w) => `${w.pou ?? ''}|${w.message}`);
    expect(text).toContainEqual(expect.stringMatching(/^PLC_PRG\|POU "PLC_PRG" is written in CFC \(CODESYS\).*kept unchanged for export.*does not run CFC.*a task that runs it runs its other programs without it/));
    expect(text).toContainEqual(expect.stringMatching(/^LampLogic\|BLINK is a block of CODESYS's Util library .* added as a library POU/));
    expect(text).toContainEqual(expect.stringMatching(/^LampLogic\|LIMITALARM is a block of CODESYS's Util library/));
    expect(text).toContainEqual(expect.stringMatching(/^LampLogic\|block type RAMP_INT is a block of CODESYS's Util library that Rungsmith does not run: imported as an external block with the pins the file wires \(IN, ASCEND, DESCEND, TIMEBASE, OUT\)/));
    // Located at the first call.
    expect(report.warnings.find((w) => w.message.startsWith('BLINK is'))).toMatchObject({ element: 'block', localId: '10000000005' });
    // Object ids: one note, not a warning per POU.
    expect(report.warnings.some((w) => /objectid/.test(w.message))).toBe(false);
    expect(report.notes).toContainEqual(expect.objectContaining({ message: expect.stringMatching(/^2 CODESYS object ids .* dropped/) }));
    expect(project.externalBlocks?.map((b) => b.name)).toEqual(['RAMP_INT']);
  });

  test('the import report counts the CFC body as CFC and the Util blocks as library, and opens the LD program the task runs', () => {
    const { project } = imported(FILE);
    expect(pouCountText(project)).toBe('4 POUs (1 LD, 1 CFC, 2 library)');
    expect(project.pous.find((p) => p.id === pouToOpen(project))?.name).toBe('LampLogic');
  });

  test('BIT members of a structure are BOOLs: no type errors, only the CFC body is refused by check', () => {
    const { project } = imported(FILE);
    const errors = checkProject(project).filter((d) => d.severity === 'error');
    expect(errors.map((d) => `${d.rule} ${d.pou}: ${d.message}`)).toEqual([
      'LD-E51 PLC_PRG: the program PLC_PRG is written in CFC, which the simulator does not run; its calls cannot run (redraw it in LD, or write it in ST)',
    ]);
  });

  test("the task's LD program runs without the CFC one; BLINK, LIMITALARM and the BIT members over scans", () => {
    const { project } = imported(FILE);
    const { program, diagnostics } = compileProgram(project, { configuration: true });
    expect(diagnostics.filter((d) => d.severity === 'warning').map((d) => d.rule)).toContain('LD-W51');
    expect(diagnostics.find((d) => d.rule === 'LD-W51')?.message).toBe(
      'the program instance PLC_PRG runs PLC_PRG, written in CFC, which the simulator does not run: the configuration runs without it',
    );
    if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
    const plc = createPlc(program, { cycleMs: 10 });
    const lamp: boolean[] = [];
    const scan = (enable: boolean, level: number) => {
      plc.setInputs({ '%IX0.0': enable, '%IW0': level });
      plc.scan();
      lamp.push(plc.read('LampLogic.Lamp') as boolean);
    };
    // BLINK: TIMEHIGH = 30 ms, TIMELOW = 20 ms on a 10 ms scan: TRUE first, for 3 scans, then 2 FALSE.
    for (let i = 0; i < 11; i++) scan(true, 50);
    expect(lamp).toEqual([true, true, true, false, false, true, true, true, false, false, true]);
    expect(plc.read('LampLogic.Status.Blinking')).toBe(true);
    // LIMITALARM with LOW 20, HIGH 80: IN 50 is in range.
    expect([plc.read('LampLogic.HighAlarm'), plc.read('LampLogic.LowAlarm'), plc.read('LampLogic.InRange')]).toEqual([false, false, true]);
    // ENABLE FALSE: OUT keeps its value (CODESYS: "output OUT is not changed").
    lamp.length = 0;
    for (let i = 0; i < 4; i++) scan(false, 90);
    expect(lamp).toEqual([true, true, true, true]);
    expect([plc.read('LampLogic.HighAlarm'), plc.read('LampLogic.LowAlarm'), plc.read('LampLogic.InRange')]).toEqual([true, false, false]);
    // The packed Alarm bit: (HighAlarm OR LowAlarm) AND Enable.
    expect(plc.read('LampLogic.Status.Alarm')).toBe(false);
    // ENABLE again: a new TIMEHIGH phase starts.
    lamp.length = 0;
    for (let i = 0; i < 6; i++) scan(true, 80);
    expect(lamp).toEqual([true, true, true, false, false, true]);
    // IN = HIGH is in range (limits included).
    expect(plc.read('LampLogic.InRange')).toBe(true);
    scan(true, 19);
    expect([plc.read('LampLogic.LowAlarm'), plc.read('LampLogic.Status.Alarm')]).toEqual([true, true]);
    // RAMP_INT is external: its output holds its initial value.
    expect(plc.read('LampLogic.Ramped')).toBe(0);
  });

  test('export gives the CFC PLC_PRG back unchanged and leaves the Util blocks to CODESYS', () => {
    const { project } = imported(FILE);
    const xml = exportPlcopen(project);
    expect(xml).toContain('<data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation"><CFC>');
    expect(xml).not.toMatch(/<pou name="BLINK"/);
    expect(xml).not.toMatch(/<pou name="LIMITALARM"/);
    const again = importPlcopen(xml);
    if (!again.ok) throw new Error(JSON.stringify(again.errors));
    expect(again.project.pous.map((p) => [p.name, p.language])).toEqual([
      ['PLC_PRG', 'FBD'],
      ['LampLogic', 'LD'],
      ['BLINK', 'ST'],
      ['LIMITALARM', 'ST'],
    ]);
  });

  test('an application exported alone (its resource in the project addData) imports and runs the same', () => {
    const text = fixture(FILE);
    const res = text.slice(text.indexOf('<resource name="Application">'), text.indexOf('</resource>') + '</resource>'.length);
    const xml = text.replace(/<instances>[\s\S]*<\/instances>/, `<instances><configurations/></instances>\n  <addData><data name="http://www.3s-software.com/plcopenxml/application" handleUnknown="implementation">${res}</data></addData>`);
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(r.project.pous.map((p) => p.name)).toEqual(['PLC_PRG', 'LampLogic', 'BLINK', 'LIMITALARM']);
    expect(r.project.tasks.map((t) => [t.name, t.programs.map((p) => p.pou)])).toEqual([['MainTask', ['PLC_PRG', 'LampLogic']]]);
    expect(r.project.globals.map((g) => g.name)).toEqual(['Enable', 'Level']);
    // Read as the project, not kept as raw addData (export would write the POUs twice).
    expect(exportPlcopen(r.project)).not.toContain('plcopenxml/application');
    const { program } = compileProgram(r.project, { configuration: true });
    expect(program).toBeDefined();
  });

  test('types named with a CODESYS library namespace (Util.BLINK, Standard.RS) are those blocks', () => {
    const xml = fixture(FILE).replace('<derived name="BLINK"/>', '<derived name="Util.BLINK"/>').replace('<derived name="RS"/>', '<derived name="Standard.RS"/>');
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(r.project.pous.find((p) => p.name === 'LampLogic')!.variables.find((v) => v.name === 'Blinker')!.type).toBe('BLINK');
    expect(r.project.pous.find((p) => p.name === 'PLC_PRG')!.variables.find((v) => v.name === 'Latch')!.type).toBe('RS');
    expect(r.project.pous.map((p) => p.name)).toContain('BLINK');
  });

  test("a file's own BLINK, or a BLINK wired with other pins, is not Util's", () => {
    const own = fixture(FILE).replace(
      '<data name="http://www.3s-software.com/plcopenxml/pou" handleUnknown="implementation">\n              <pou name="PLC_PRG"',
      '<data name="http://www.3s-software.com/plcopenxml/pou" handleUnknown="implementation"><pou name="BLINK" pouType="functionBlock"><interface><inputVars><variable name="ENABLE"><type><BOOL/></type></variable><variable name="TIMELOW"><type><TIME/></type></variable><variable name="TIMEHIGH"><type><TIME/></type></variable></inputVars><outputVars><variable name="OUT"><type><BOOL/></type></variable></outputVars></interface><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">OUT := ENABLE;</xhtml></ST></body></pou></data>\n            <data name="http://www.3s-software.com/plcopenxml/pou" handleUnknown="implementation">\n              <pou name="PLC_PRG"',
    );
    const r = importPlcopen(own);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(r.project.pous.filter((p) => p.name === 'BLINK')).toHaveLength(1);
    expect(r.project.pous.find((p) => p.name === 'BLINK')?.source).toBe('OUT := ENABLE;');
    const otherPins = fixture(FILE).replace('formalParameter="TIMELOW"', 'formalParameter="PERIOD"');
    const r2 = importPlcopen(otherPins);
    if (!r2.ok) throw new Error(JSON.stringify(r2.errors));
    expect(r2.project.pous.map((p) => p.name)).not.toContain('BLINK');
    expect(r2.project.externalBlocks?.map((b) => b.name)).toContain('BLINK');
  });

  test("Util's HYSTERESIS (IN, HIGH, LOW -> OUT) is named where it meets the annex F HYSTERESIS of the same name", () => {
    const xml = fixture(FILE)
      .replace('typeName="LIMITALARM"', 'typeName="HYSTERESIS"')
      .replace('<derived name="LIMITALARM"/>', '<derived name="HYSTERESIS"/>')
      .replace('<variable formalParameter="O"><connectionPointOut><expression/></connectionPointOut></variable><variable formalParameter="U"><connectionPointOut><expression/></connectionPointOut></variable><variable formalParameter="IL"><connectionPointOut><expression/></connectionPointOut></variable>', '<variable formalParameter="OUT"><connectionPointOut><expression/></connectionPointOut></variable>');
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(r.report.warnings).toContainEqual(
      expect.objectContaining({
        pou: 'LampLogic',
        localId: '20000000005',
        message:
          "HYSTERESIS is called with pins of CODESYS Util's HYSTERESIS (IN, HIGH, LOW, OUT); Rungsmith's HYSTERESIS is the annex F block of OpenPLC's library (XIN1, XIN2, EPS -> Q), and Util's HYSTERESIS is not supported: the wires of those pins are dropped and the call does not do what it does in CODESYS",
      }),
    );
    // The coil the file wires from output O (which the annex F block does not have) keeps no wire from it.
    expect(r.report.warnings.map((w) => w.message)).toContainEqual(
      expect.stringMatching(/^the wire from output O of block HYSTERESIS \(localId 20000000005\) cannot be kept: HYSTERESIS has no pin O$/),
    );
  });

  test('REFERENCE TO and POINTER TO variables keep their base type with a named warning', () => {
    const xml = fixture(FILE).replace(
      '<variable name="Ramped"><type><INT/></type></variable>',
      '<variable name="Ramped"><type><INT/></type></variable><variable name="LevelRef"><type><derived name="REFERENCE TO INT"/></type></variable><variable name="LevelPtr"><type><pointer><baseType><INT/></baseType></pointer></type></variable>',
    );
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    const lamp = r.project.pous.find((p) => p.name === 'LampLogic')!;
    expect(lamp.variables.filter((v) => v.name === 'LevelRef' || v.name === 'LevelPtr').map((v) => v.type)).toEqual(['INT', 'INT']);
    const msgs = r.report.warnings.map((w) => w.message);
    expect(msgs).toContain('a REFERENCE TO type is not supported by Rungsmith; the variable keeps the name of its base type INT');
    expect(msgs).toContain('a pointer type is not supported by Rungsmith; the variable keeps the name of its base type');
  });

  test('an SFC transition wired from a variable holding an ST expression (as CODESYS writes every condition) runs it', () => {
    const X = 'xmlns="http://www.w3.org/1999/xhtml"';
    const xml = `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP18" creationDateTime="2026-11-28T10:00:00"/>
  <contentHeader name="seq.project"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="PLC_PRG" pouType="program">
      <interface><localVars>
        <variable name="Count"><type><INT/></type></variable>
        <variable name="Limit"><type><INT/></type><initialValue><simpleValue value="3"/></initialValue></variable>
        <variable name="Finished"><type><BOOL/></type></variable>
      </localVars></interface>
      <actions><action name="CountUp"><body><ST><xhtml ${X}>Count := Count + 1;</xhtml></ST></body></action></actions>
      <body><SFC>
        <step localId="0" initialStep="true" name="Init"><position x="0" y="0"/><connectionPointIn/><connectionPointOut formalParameter="sfc"/></step>
        <actionBlock localId="1"><position x="0" y="0"/><connectionPointIn><connection refLocalId="0"/></connectionPointIn>
          <action localId="2" qualifier="N"><relPosition x="0" y="0"/><reference name="CountUp"/><connectionPointOut/></action></actionBlock>
        <inVariable localId="3"><position x="0" y="0"/><connectionPointOut/><expression>Count &gt;= Limit AND NOT Finished</expression></inVariable>
        <transition localId="4"><position x="0" y="0"/><connectionPointIn><connection refLocalId="0" formalParameter="sfc"/></connectionPointIn>
          <condition><connectionPointIn><connection refLocalId="3"/></connectionPointIn></condition></transition>
        <step localId="5" initialStep="false" name="Done"><position x="0" y="0"/><connectionPointIn><connection refLocalId="4" formalParameter="sfc"/></connectionPointIn><connectionPointOut formalParameter="sfc"/></step>
        <actionBlock localId="6"><position x="0" y="0"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn>
          <action localId="7" qualifier="N"><relPosition x="0" y="0"/><reference name="Finished"/><connectionPointOut/></action></actionBlock>
      </SFC></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>`;
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    const { program, diagnostics } = compileProgram(r.project, { pou: 'PLC_PRG' });
    if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
    const plc = createPlc(program, { cycleMs: 10 });
    const seen: [number, boolean][] = [];
    for (let i = 0; i < 6; i++) {
      plc.scan();
      seen.push([plc.read('Count') as number, plc.read('Finished') as boolean]);
    }
    // CountUp runs while Init is active; Count >= 3 moves to Done, which sets Finished.
    expect(seen).toEqual([
      [1, false],
      [2, false],
      [3, false],
      [3, true],
      [3, true],
      [3, true],
    ]);
  });

  test('enum values qualified with a dot (E_STATE.BUSY, as CODESYS writes them) in initial values and ST', () => {
    const X = 'xmlns="http://www.w3.org/1999/xhtml"';
    const xml = `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP19" creationDateTime="2026-11-28T10:00:00"/>
  <contentHeader name="enum.project"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types>
    <dataTypes><dataType name="E_STATE"><baseType><enum><values><value name="IDLE"/><value name="BUSY"/><value name="DONE"/></values></enum></baseType></dataType></dataTypes>
    <pous><pou name="PLC_PRG" pouType="program">
      <interface><localVars>
        <variable name="State"><type><derived name="E_STATE"/></type><initialValue><simpleValue value="E_STATE.BUSY"/></initialValue></variable>
        <variable name="Steps"><type><INT/></type></variable>
      </localVars></interface>
      <body><ST><xhtml ${X}>IF State = E_STATE.BUSY THEN Steps := Steps + 1; END_IF;
IF Steps &gt;= 2 THEN State := E_STATE.DONE; END_IF;</xhtml></ST></body>
    </pou></pous>
  </types>
  <instances><configurations/></instances>
</project>`;
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    const { program, diagnostics } = compileProgram(r.project, { pou: 'PLC_PRG' });
    if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
    const plc = createPlc(program, { cycleMs: 10 });
    expect(plc.read('State')).toBe(1);
    plc.scans(4);
    expect([plc.read('State'), plc.read('Steps')]).toEqual([2, 2]);
  });

  test("CODESYS's input names of the standard counters and bistables (CTU.RESET, SR.SET1/RESET) are the IEC pins, in LD and ST", () => {
    const xml = ldXml(
      [
        { name: 'Pulse', type: 'BOOL' },
        { name: 'Clear', type: 'BOOL' },
        { name: 'Full', type: 'BOOL' },
        { name: 'Count', type: 'INT' },
        { name: 'Parts', type: 'CTU' },
        { name: 'Latch', type: 'SR' },
        { name: 'Held', type: 'BOOL' },
      ],
      [
        {
          objects: [
            { id: 1, kind: 'contact', v: 'Pulse', in: ['rail'] },
            { id: 2, kind: 'contact', v: 'Clear', in: ['rail'] },
            { id: 3, kind: 'block', type: 'CTU', instance: 'Parts', inputs: { CU: ['1'], RESET: ['2'], PV: ['=2'] }, outputs: ['Q', 'CV'], assign: { CV: 'Count' } },
            { id: 4, kind: 'coil', v: 'Full', in: ['3.Q'] },
          ],
          toRail: [4],
        },
        {
          objects: [
            { id: 5, kind: 'block', type: 'SR', instance: 'Latch', inputs: { SET1: ['=Full'], RESET: ['=Clear'] }, outputs: ['Q1'], assign: { Q1: 'Held' } },
          ],
        },
      ],
    );
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(r.report.warnings.filter((w) => /not a pin/.test(w.message))).toEqual([]);
    expect(r.report.notes.map((n) => n.message)).toContain(
      "inputs named as in CODESYS's Standard library read as the IEC pins: CTU.RESET as R, SR.SET1 as S1, SR.RESET as R (export writes the IEC names)",
    );
    const { program, diagnostics } = compileProgram(r.project, { pou: r.project.pous[0]!.name });
    if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
    const plc = createPlc(program, { cycleMs: 10 });
    const step = (pulse: boolean, clear: boolean) => {
      plc.write('Pulse', pulse);
      plc.write('Clear', clear);
      plc.scan();
      return [plc.read('Count'), plc.read('Full'), plc.read('Held')];
    };
    expect(step(true, false)).toEqual([1, false, false]);
    step(false, false);
    expect(step(true, false)).toEqual([2, true, true]);
    // RESET (IEC R) clears the count; SR's RESET (IEC R) drops the latch.
    expect(step(false, true)).toEqual([0, false, false]);

    // The same names in an ST call.
    const st = fixture(FILE).replace('<ST><xhtml xmlns="http://www.w3.org/1999/xhtml" /></ST>', '<ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Latch(SET := Start, RESET1 := Stop);\nRunning := Latch.Q1;</xhtml></ST>').replace(/<addData><data name="http:\/\/www.3s-software.com\/plcopenxml\/cfc"[\s\S]*?<\/CFC><\/data><\/addData>/, '');
    const r2 = importPlcopen(st);
    if (!r2.ok) throw new Error(JSON.stringify(r2.errors));
    const prg = r2.project.pous.find((p) => p.name === 'PLC_PRG')!;
    expect(prg.language).toBe('ST');
    const c2 = compileProgram(r2.project, { pou: 'PLC_PRG' });
    if (!c2.program) throw new Error(c2.diagnostics.map((d) => d.message).join('\n'));
    const plc2 = createPlc(c2.program, { cycleMs: 10 });
    plc2.setInputs({ '%IX0.1': true, '%IX0.2': false });
    plc2.scan();
    expect(plc2.read('Running')).toBe(true);
    plc2.setInputs({ '%IX0.1': true, '%IX0.2': true });
    plc2.scan();
    expect(plc2.read('Running')).toBe(false);
  });
});
