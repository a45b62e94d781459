// The profile an import chooses (issue 12: OpenPLC/Beremiz files -> openplc) and its round trip
// through Rungsmith's own export.
import { describe, expect, it } from 'vitest';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { chooseProfile } from '../../src/plcopen/profileChoice';
import type { Profile, Project } from '../../src/model/project';
import { imported, run } from './fixtures';
import { schemaErrors } from './xsd';

function reimport(project: Project) {
  const r = importPlcopen(exportPlcopen(project));
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r;
}

describe('the profile an imported file runs under', () => {
  it('TC6 v2.01 (Beremiz, OpenPLC v3/v4) and v1.0 (PLCOpenEditor) run as MATIEC compiles them; v2.0 (CODESYS, TwinCAT) as IEC', () => {
    expect(
      chooseProfile({ namespace: 'http://www.plcopen.org/xml/tc6_0201', companyName: 'Unknown' }).profile,
    ).toBe('openplc');
    expect(chooseProfile({ namespace: 'http://www.plcopen.org/xml/tc6.xsd' }).reason).toMatch(
      /openplc: PLCopen TC6 v1\.0/,
    );
    expect(
      chooseProfile({
        namespace: 'http://www.plcopen.org/xml/tc6_0200',
        companyName: 'CODESYS Development GmbH',
      }).profile,
    ).toBe('iec');
    // A file Rungsmith wrote before it recorded the profile was iec, Rungsmith's default then.
    expect(
      chooseProfile({ namespace: 'http://www.plcopen.org/xml/tc6_0201', companyName: 'Rungsmith' }).profile,
    ).toBe('iec');
    // A record wins; an unknown value in it is ignored.
    expect(
      chooseProfile({ namespace: 'http://www.plcopen.org/xml/tc6_0200', recorded: 'openplc' }).profile,
    ).toBe('openplc');
    expect(
      chooseProfile({ namespace: 'http://www.plcopen.org/xml/tc6_0201', recorded: 'codesys' }).profile,
    ).toBe('openplc');
  });

  it('an OpenPLC-style file imports under openplc and runs as the generated ST does (a shared contact read again)', () => {
    const { project, report } = imported('openplc-order.xml');
    expect(project.profile).toBe('openplc');
    expect(report.profileReason).toMatch(/^semantics profile openplc/);
    // IF B THEN B := FALSE; END_IF; Y := B;  ->  Y sees B after the reset coil wrote it.
    const plc = run(project, 'Main');
    plc.write('B', true);
    plc.scan();
    expect([plc.read('B'), plc.read('Y')]).toEqual([false, false]);
    const iec = run({ ...project, profile: 'iec' }, 'Main');
    iec.write('B', true);
    iec.scan();
    expect([iec.read('B'), iec.read('Y')]).toEqual([false, true]);
  });

  it.each<Profile>(['iec', 'openplc'])(
    'Rungsmith export records %s; importing it gives the same profile, and the file stays schema-valid',
    async (profile) => {
      const { project } = imported('openplc-order.xml');
      const xml = exportPlcopen({ ...project, profile });
      expect(xml).toContain(
        `<data name="rungsmith:profile" handleUnknown="discard"><profile xmlns="urn:rungsmith" name="${profile}"/></data>`,
      );
      expect(await schemaErrors(xml, 'profile.xml')).toEqual([]);
      const back = reimport({ ...project, profile });
      expect(back.project.profile).toBe(profile);
      expect(back.report.profileReason).toBe(
        `semantics profile ${profile}, as recorded by Rungsmith in the file`,
      );
      // The record is read, not kept as foreign addData (exporting again writes it once).
      expect(exportPlcopen(back.project).split('rungsmith:profile')).toHaveLength(2);
      expect(back.report.warnings).toEqual([]);
    },
  );
});
