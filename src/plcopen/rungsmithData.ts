// What Rungsmith writes in PLCopen addData so that its own import gets a project back whole, and
// other tools ignore (every `data` is handleUnknown="discard", its content in Rungsmith's
// namespace, RS_NS; the TC6 v2.01 schema takes any element there, processContents="lax"):
//
// - a library's POU is exported as an ordinary `<pou>` (Beremiz, OpenPLC and CODESYS compile it)
//   marked in its own addData: `<data name="https://rungsmith.dev/plcopen/library">
//   <library xmlns="https://rungsmith.dev/plcopen" name="Conveyors"/></data>`;
// - the project's addData lists its libraries with their version:
//   `<data name=".../libraries"><libraries xmlns="..."><library name hash sourceFile addedAt origin>
//   <pou name="Conveyor"/><dataType name="Speed"/></library></libraries></data>`;
// - the project's scenarios (docs/scenarios.md): `<data name=".../scenarios"><scenarios xmlns="...">
//   <scenario name="fill cycle">CSV text</scenario></scenarios></data>` (line breaks as &#10;);
// - the machine the project controls (docs/PLANTS.md) and the addresses the user changed:
//   `<data name=".../plant"><plant xmlns="..." id="tank"><point name="Pump" address="%QX1.0"/>
//   </plant></data>`.
// Pure: no DOM.
import { libraryPou } from '../model/libraries';
import type { Pou, ProjectLibrary, ProjectPlant, Scenario } from '../model/project';
import { childrenNamed, type XmlElement } from './xml/parse';
import { escapeAttr } from './xml/write';
import { RS_NS, preserved, type PreservedPou } from './types';

export const RS_LIBRARY = `${RS_NS}/library`;
export const RS_LIBRARIES = `${RS_NS}/libraries`;
export const RS_SCENARIOS = `${RS_NS}/scenarios`;
export const RS_PLANT = `${RS_NS}/plant`;

/** The addData `data` that marks an exported POU as a block of the library `name`. */
export const libraryMark = (name: string): string =>
  `<data name="${RS_LIBRARY}" handleUnknown="discard"><library xmlns="${RS_NS}" name="${escapeAttr(name)}"/></data>`;

/** The project-level `data` listing the libraries (name, version, source, contents). */
export function librariesData(libraries: readonly ProjectLibrary[]): string {
  const lines = [`<data name="${RS_LIBRARIES}" handleUnknown="discard">`, `  <libraries xmlns="${RS_NS}">`];
  for (const l of libraries) {
    lines.push(
      `    <library name="${escapeAttr(l.name)}" hash="${escapeAttr(l.hash)}" sourceFile="${escapeAttr(l.sourceFile)}" addedAt="${escapeAttr(l.addedAt)}" origin="${l.origin}">`,
    );
    for (const p of l.pous) lines.push(`      <pou name="${escapeAttr(p.name)}"/>`);
    for (const d of l.dataTypes ?? []) lines.push(`      <dataType name="${escapeAttr(d.name)}"/>`);
    lines.push('    </library>');
  }
  lines.push('  </libraries>', '</data>');
  return lines.join('\n');
}

/** Scenario text as XML character data on one line (escapeAttr also encodes line breaks and tabs). */
const textData = (s: string): string => escapeAttr(s).replace(/&quot;/g, '"');

/** The project-level `data` holding the scenarios. */
export function scenariosData(scenarios: readonly Scenario[]): string {
  return [
    `<data name="${RS_SCENARIOS}" handleUnknown="discard">`,
    `  <scenarios xmlns="${RS_NS}">`,
    ...scenarios.map((s) => `    <scenario name="${escapeAttr(s.name)}">${textData(s.csv)}</scenario>`),
    '  </scenarios>',
    '</data>',
  ].join('\n');
}

/** The project-level `data` naming the machine the project controls and its changed addresses. */
export function plantData(plant: ProjectPlant): string {
  const points = Object.entries(plant.map ?? {});
  const open = `  <plant xmlns="${RS_NS}" id="${escapeAttr(plant.id)}"`;
  return [
    `<data name="${RS_PLANT}" handleUnknown="discard">`,
    ...(points.length
      ? [
          `${open}>`,
          ...points.map(([name, address]) => `    <point name="${escapeAttr(name)}" address="${escapeAttr(address)}"/>`),
          '  </plant>',
        ]
      : [`${open}/>`]),
    '</data>',
  ].join('\n');
}

/** The machine of a project-level `data` (the first `plant` with an id), if it names one. */
export function readPlantData(data: XmlElement): ProjectPlant | undefined {
  const plant = childrenNamed(data, 'plant').find((p) => p.attrs.id);
  if (!plant) return undefined;
  const map: Record<string, string> = {};
  for (const p of childrenNamed(plant, 'point')) if (p.attrs.name && p.attrs.address) map[p.attrs.name] = p.attrs.address;
  return Object.keys(map).length ? { id: plant.attrs.id!, map } : { id: plant.attrs.id! };
}

/** The library named by a POU's mark, if the `data` is one. */
export function readLibraryMark(data: XmlElement): string | undefined {
  if (data.attrs.name !== RS_LIBRARY) return undefined;
  return childrenNamed(data, 'library')[0]?.attrs.name;
}

export interface LibraryManifest {
  readonly name: string;
  readonly hash: string;
  readonly sourceFile: string;
  readonly addedAt: string;
  readonly origin: ProjectLibrary['origin'];
  readonly pous: readonly string[];
  readonly dataTypes: readonly string[];
}

const HASH = /^sha256:[0-9a-f]{64}$/;

/** The libraries listed in a project-level `data`; `bad` gets the entries that cannot be used. */
export function readLibrariesData(data: XmlElement, bad: (message: string, el: XmlElement) => void): LibraryManifest[] {
  const out: LibraryManifest[] = [];
  for (const list of childrenNamed(data, 'libraries'))
    for (const l of childrenNamed(list, 'library')) {
      const a = l.attrs;
      if (!a.name || !a.hash || !HASH.test(a.hash)) {
        bad(`the library entry "${a.name ?? ''}" has no name or no valid hash (sha256:<64 hex digits>): its blocks are read as POUs of the project`, l);
        continue;
      }
      out.push({
        name: a.name,
        hash: a.hash,
        sourceFile: a.sourceFile ?? '',
        addedAt: a.addedAt ?? '',
        origin: a.origin === 'rungsmith' ? 'rungsmith' : 'plcopen',
        pous: childrenNamed(l, 'pou').map((p) => p.attrs.name ?? ''),
        dataTypes: childrenNamed(l, 'dataType').map((p) => p.attrs.name ?? ''),
      });
    }
  return out;
}

/** The scenarios of a project-level `data`. */
export function readScenariosData(data: XmlElement): Scenario[] {
  return childrenNamed(data, 'scenarios').flatMap((list) =>
    childrenNamed(list, 'scenario')
      .filter((s) => s.attrs.name)
      .map((s) => ({ name: s.attrs.name!, csv: s.text })),
  );
}

/**
 * A POU as a library keeps it: its library id, and without the `<pou>` a PLCopen file kept
 * verbatim (export writes a library POU anew, with its mark).
 */
export function asLibraryPou(library: string, pou: Pou): Pou {
  const keep = preserved<PreservedPou>(pou.extensions);
  let extensions = pou.extensions;
  if (keep?.pou !== undefined) {
    const { pou: _raw, fingerprint: _fp, ...rest } = keep;
    const { plcopen: _p, ...others } = pou.extensions ?? {};
    extensions = Object.keys(rest).length ? { ...others, plcopen: rest } : others;
  }
  const { extensions: _e, ...bare } = pou;
  return libraryPou(library, extensions && Object.keys(extensions).length ? { ...bare, extensions } : bare);
}
