// Graphical transition conditions with a feedback loop (PLCopen FBD wired to a transition): MATIEC
// orders the blocks depth first from the condition; a wire back to a block still being computed
// reads the value of the previous call. Through an FB instance's output that value is kept (the
// wire reads `Instance.Pin`); through a function, the loop stays drawn and the engine reads the
// function's result of its previous call (Beremiz's `_TMP_AND20_OUT`), with LD-W30.
import { describe, expect, it } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { importPlcopen } from '../../src/plcopen/importPlcopen';

const at = (x: number, y: number) => `<position x="${x}" y="${y}"/>`;
const out = (id: number, pin?: string) => `<connection refLocalId="${id}"${pin ? ` formalParameter="${pin}"` : ''}/>`;
const input = (pin: string, wire: string) =>
  `<variable formalParameter="${pin}"><connectionPointIn><relPosition x="0" y="10"/>${wire}</connectionPointIn></variable>`;
const output = (pin: string) => `<variable formalParameter="${pin}"><connectionPointOut><relPosition x="40" y="10"/></connectionPointOut></variable>`;
const block = (id: number, type: string, ins: string, outs: string, instance?: string) =>
  `<block localId="${id}" width="60" height="60" typeName="${type}"${instance ? ` instanceName="${instance}"` : ''}>${at(300, 100 + id * 10)}<inputVariables>${ins}</inputVariables><inOutVariables/><outputVariables>${outs}</outputVariables></block>`;
const inVar = (id: number, expr: string) =>
  `<inVariable localId="${id}" height="30" width="60">${at(100, 100 + id * 10)}<connectionPointOut><relPosition x="60" y="15"/></connectionPointOut><expression>${expr}</expression></inVariable>`;

/** A PROGRAM Main: Init --(condition wired to `cond`)--> Done, with the condition's graphics. */
function project(vars: string, graphics: string, cond: string): string {
  return `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program">
      <interface><localVars>${vars}</localVars></interface>
      <body><SFC>
        <step localId="1" name="Init" initialStep="true">${at(100, 20)}<connectionPointOut formalParameter=""><relPosition x="20" y="30"/></connectionPointOut></step>
        <transition localId="2" height="2" width="20">${at(110, 80)}
          <connectionPointIn><relPosition x="10" y="0"/>${out(1)}</connectionPointIn>
          <connectionPointOut><relPosition x="10" y="2"/></connectionPointOut>
          <condition><connectionPointIn><relPosition x="0" y="1"/>${cond}</connectionPointIn></condition></transition>
        <step localId="3" name="Done" initialStep="false">${at(100, 400)}<connectionPointIn><relPosition x="20" y="0"/>${out(2)}</connectionPointIn></step>
        ${graphics}
      </SFC></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R">
    <task name="T" priority="0" interval="T#100ms"><pouInstance name="inst" typeName="Main"/></task>
  </resource></configuration></configurations></instances>
</project>`;
}

const variable = (name: string, type: string) => `<variable name="${name}"><type>${/^[A-Z]+$/.test(type) && type !== 'TON' && type !== 'SR' ? `<${type}/>` : `<derived name="${type}"/>`}</type></variable>`;

describe('SFC graphical conditions with a feedback loop', () => {
  it('through FB outputs: the fed-back wire reads the previous call (SR0.R from TON0.Q, TON0.IN from SR0.Q1)', () => {
    const xml = project(
      [variable('Req', 'BOOL'), variable('SR0', 'SR'), variable('TON0', 'TON')].join(''),
      [
        inVar(10, 'Req'),
        inVar(11, 'T#300ms'),
        block(20, 'SR', input('S1', out(10)) + input('R', out(21, 'Q')), output('Q1'), 'SR0'),
        block(21, 'TON', input('IN', out(20, 'Q1')) + input('PT', out(11)), output('Q') + output('ET'), 'TON0'),
      ].join(''),
      out(21, 'Q'),
    );
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    const { program, diagnostics } = compileProgram(r.project, {});
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 100 });
    const row = () => [plc.read('Init.X'), plc.read('SR0.Q1'), plc.read('TON0.Q')].map(Number);
    // Scan 1 (t = 0) stores COMPUTE_FUNCTION_BLOCKS (SR0, TON0) on Init; they run from scan 1 on.
    plc.scan();
    expect(row()).toEqual([1, 0, 0]);
    plc.write('Req', true);
    plc.scan(); // t = 100: SR0 set, TON0 starts
    plc.write('Req', false);
    expect(row()).toEqual([1, 1, 0]);
    plc.scans(2); // t = 300
    expect(row()).toEqual([1, 1, 0]);
    plc.scan(); // t = 400: TON0's ET = 300 ms: Q; SR0 read TON0.Q of the previous call (FALSE)
    expect(row()).toEqual([1, 1, 1]);
    plc.scan(); // the transition reads Q of the previous call: Init -> Done; SR0 reset, TON0 off
    expect(row()).toEqual([0, 0, 0]);
  });

  it('through a function: the loop runs (LD-W30), the function reading its result of the previous call (FALSE at first)', () => {
    const xml = project(
      variable('A', 'BOOL'),
      [inVar(10, 'A'), block(20, 'AND', input('IN1', out(10)) + input('IN2', out(20, 'OUT')), output('OUT'))].join(''),
      out(20, 'OUT'),
    );
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    const { program, diagnostics } = compileProgram(r.project, {});
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    expect(diagnostics.filter((d) => d.rule === 'LD-W30').map((d) => d.message)).toEqual([expect.stringMatching(/^the AND block .* feeds back into its own input/)]);
    const plc = createPlc(program!, { cycleMs: 100 });
    plc.write('A', true);
    // AND(A, its previous result): FALSE at first, so FALSE for ever: the chart stays on Init.
    plc.scans(4);
    expect(Number(plc.read('Init.X'))).toBe(1);
  });
});
