// Real OpenPLC Editor exports (MIT/BSD, copied with attribution in tests/fixtures/plcopen/corpus).
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { imported, run } from './fixtures';
import { schemaErrors } from './xsd';

const FILES = [
  'openplc-v4__felipewoo_main.xml',
  'idaholab__SPEMMCRA_DNP3test.xml',
  'godardhi0__dancinglights.xml',
  'estidlore__parking_automation.xml',
  'sakunamary__roaster.xml',
  'sakunamary__i2c_test.xml',
  'virajdesai__01_coil_and_contact.xml',
  'virajdesai__05_xor_xnor.xml',
];

describe('real OpenPLC files', () => {
  it.each(FILES)('%s: imports with every wire drawn exactly, re-exports valid v2.01', async (file) => {
    const { project, report } = imported(`corpus/${file}`);
    expect(report.warnings.filter((w) => /cannot be drawn/.test(w.message))).toEqual([]);
    expect(project.pous.length).toBeGreaterThan(0);
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml)).toEqual([]);
    expect(importPlcopen(xml).ok).toBe(true);
  });

  it('OpenPLC v4: formalParameter on rail/contact sources is ignored; the OR merge becomes a branch', () => {
    const { project } = imported('corpus/openplc-v4__felipewoo_main.xml');
    const first = project.pous[0]!.networks[0]!;
    expect(first.vlinks.length).toBeGreaterThan(0);
    expect(checkProject(project).filter((d) => d.severity === 'error')).toEqual([]);
    const plc = run(project, 'main');
    plc.write('start', true);
    plc.scan();
    expect(plc.read('coil')).toBe(true);
    plc.write('start', false);
    plc.scan();
    expect(plc.read('coil')).toBe(true); // sealed in through its own contact
    plc.write('stop', true);
    plc.scan();
    expect(plc.read('coil')).toBe(false);
  });

  it('coils feeding coils and a negated coil fed by an OR of two coil outputs', () => {
    const { project } = imported('corpus/idaholab__SPEMMCRA_DNP3test.xml');
    const net = project.pous[0]!.networks[0]!;
    expect(
      net.elements.filter((e) => e.kind === 'coil').map((e) => (e.kind === 'coil' ? e.coil : '')),
    ).toContain('NEG');
    expect(net.elements.some((e) => e.kind === 'contact')).toBe(false);
  });

  it('a contact shared by branches that merge differently is drawn twice (dancing lights)', () => {
    const { project, report } = imported('corpus/godardhi0__dancinglights.xml');
    expect(project.pous[0]!.networks).toHaveLength(15);
    expect(report.warnings.some((w) => /drawn twice/.test(w.message))).toBe(true);
    expect(checkProject(project).filter((d) => d.severity === 'error' && d.rule !== 'LD-R03')).toEqual([]);
  });

  it('non-ASCII text, an FBD block kept verbatim, two programs in two tasks', () => {
    const roaster = imported('corpus/sakunamary__roaster.xml');
    expect(roaster.report.producer).toContain('HB-M2s控制板');
    // The FBD function block is kept verbatim for export, constants and non-ASCII comments included.
    const xml = exportPlcopen(roaster.project);
    expect(xml).toContain('<pou name="PT_Calc" pouType="functionBlock">');
    expect(xml).toContain('<localVars constant="true">');
    expect(xml).toContain('<![CDATA[Temp < 0°C]]>');
    const i2c = imported('corpus/sakunamary__i2c_test.xml');
    expect(i2c.project.tasks.map((t) => [t.name, t.cycleMs, t.programs[0]!.pou])).toEqual([
      ['task0', 20, 'main'],
      ['task1', 1000, 'get_temp'],
    ]);
  });
});
