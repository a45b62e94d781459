// STRING and WSTRING through PLCopen: <string/>, <wstring/>, <string length="20"/>, string initial
// values and literals on block pins, exported valid against TC6 v2.01 and imported back unchanged.
import { describe, expect, it } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { canonical } from './fixtures';
import { schemaErrors } from './xsd';

function stringProject() {
  const net = newNetwork({
    rows: 4,
    cols: 5,
    elements: [
      { id: 'l1' as ElementId, kind: 'link', row: 0, col: 0 },
      {
        id: 'b1' as ElementId,
        kind: 'box',
        row: 0,
        col: 1,
        blockType: 'CONCAT',
        inputs: { IN1: 'Greeting', IN2: "', it$'s me$N'" },
        outputs: { OUT: 'Msg' },
      },
    ],
    vlinks: [],
  });
  const main = newPou('Main', {
    variables: [
      variable('Greeting', 'STRING', { initial: "'Hello'" }),
      variable('Msg', 'STRING'),
      variable('Code', 'STRING[20]', { initial: "'A1'" }),
      variable('Wide', 'WSTRING', { initial: '"$20AC 5"' }),
    ],
    networks: [net],
  });
  return newProject('Strings', { pous: [main] });
}

describe('PLCopen STRING and WSTRING', () => {
  it('exports <string/>, <wstring/> and <string length="20"/> valid against the schema', async () => {
    const xml = exportPlcopen(stringProject());
    expect(xml).toContain('<string/>');
    expect(xml).toContain('<wstring/>');
    expect(xml).toContain('<string length="20"/>');
    expect(xml).toContain(`<simpleValue value="'Hello'"/>`);
    expect(await schemaErrors(xml, 'strings.xml')).toEqual([]);
  });

  it('imports back the same project, which runs', () => {
    const p = stringProject();
    const again = importPlcopen(exportPlcopen(p));
    if (!again.ok) throw new Error(JSON.stringify(again.errors));
    const third = importPlcopen(exportPlcopen(again.project));
    expect(third.ok && canonical(third.project)).toBe(canonical(again.project));
    const vars = again.project.pous[0]!.variables.map((v) => `${v.name}:${v.type}:${v.initial ?? ''}`);
    expect(vars).toEqual(["Greeting:STRING:'Hello'", 'Msg:STRING:', "Code:STRING[20]:'A1'", 'Wide:WSTRING:"$20AC 5"']);
    const { program, diagnostics } = compileProgram(again.project, {});
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 10 });
    plc.scan();
    expect(plc.read('Msg')).toBe("Hello, it's me\n");
    expect(plc.read('Wide')).toBe('€ 5');
  });
});
