// Which semantics profile an imported PLCopen file runs under (issue 12: "OpenPLC/Beremiz files ->
// openplc", LD-SEMANTICS.md section 10), and how Rungsmith's own export records the profile so that
// export then import gives the project back as it was.
// - A file Rungsmith wrote carries its profile in a project-level addData element
//   (`<data name="rungsmith:profile"><profile xmlns="urn:rungsmith" name="openplc"/></data>`).
// - Otherwise the namespace tells the writer (shared/plcopen/NOTES.md section 1): TC6 v2.01
//   (`tc6_0201`) is what Beremiz, OpenPLC v3 and OpenPLC v4 write, and the v1.0 namespace
//   (`tc6.xsd`) is what 2007-era PLCOpenEditor/Beremiz wrote: both run as MATIEC compiles them
//   (`openplc`). CODESYS and TwinCAT write v2.0 (`tc6_0200`): `iec`.
// - A file whose fileHeader says Rungsmith but has no profile record (written before the record
//   existed) was `iec`, Rungsmith's default then.
// Pure: no DOM.
import type { Profile } from '../model/project';

/** The name of the addData `data` element that records the profile. */
export const PROFILE_DATA_NAME = 'rungsmith:profile';
const PROFILES: readonly Profile[] = ['iec', 'openplc'];

export interface ProfileChoice {
  readonly profile: Profile;
  /** For the import report: why this profile (`semantics profile openplc: ...`). */
  readonly reason: string;
}

export interface ProfileEvidence {
  /** The root element's default namespace. */
  readonly namespace: string;
  readonly companyName?: string;
  /** The `name` attribute of the `profile` element inside the `rungsmith:profile` data, if any. */
  readonly recorded?: string;
}

export function chooseProfile(e: ProfileEvidence): ProfileChoice {
  const recorded = PROFILES.find((p) => p === e.recorded);
  if (recorded)
    return {
      profile: recorded,
      reason: `semantics profile ${recorded}, as recorded by Rungsmith in the file`,
    };
  if (e.companyName === 'Rungsmith')
    return {
      profile: 'iec',
      reason: `semantics profile iec: the file was written by Rungsmith without a profile record`,
    };
  if (/tc6_0201$/.test(e.namespace) || /tc6\.xsd$/.test(e.namespace))
    return {
      profile: 'openplc',
      reason: `semantics profile openplc: PLCopen ${/tc6_0201$/.test(e.namespace) ? 'TC6 v2.01' : 'TC6 v1.0'} is written by Beremiz and OpenPLC, so the program runs as MATIEC compiles it (evaluation order, counters, TIME conversions: LD-SEMANTICS section 10)`,
    };
  return { profile: 'iec', reason: `semantics profile iec (the IEC 61131-3 text)` };
}

/** The addData `data` element that records the profile in an export. */
export function profileData(profile: Profile): string {
  return `<data name="${PROFILE_DATA_NAME}" handleUnknown="discard"><profile xmlns="urn:rungsmith" name="${profile}"/></data>`;
}
