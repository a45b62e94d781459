// A whole project → one PLCopen TC6 XML v2.01 document.
import { blockLibrary, type BlockLibrary } from '../model/library';
import type { Pou, Project } from '../model/project';
import { formatInterval } from './durations';
import { uniqueConnectorNames } from './connectorNames';
import { writeNetwork } from './exportBody';
import { writeType, writeVarLists } from './exportInterface';
import { writeInterface, writeOtherPou } from './otherPous';
import { NETWORK_GAP, SCALING } from './geometry';
import { TC6_0201, XHTML_NS, preserved, type PreservedPou, type PreservedProject } from './types';
import { XmlWriter } from './xml/write';
import { writeDataTypes } from './dataTypes';
import { profileData } from './profileChoice';
import { librariesData, libraryMark, plantData, scenariosData } from './rungsmithData';
import { externalsMark, missingExternals, needsExternals } from './addedExternals';

export interface ExportOptions {
  /** Timestamp written in fileHeader/contentHeader (default: now). */
  readonly now?: Date;
}

const POU_TYPE = { PROGRAM: 'program', FUNCTION_BLOCK: 'functionBlock', FUNCTION: 'function' } as const;

const isoSeconds = (d: Date): string => d.toISOString().slice(0, 19);

/** Variables written by retentive coils (M, SM, RM) in a POU, upper-cased. */
function retainedByCoil(pou: Pou): Set<string> {
  const out = new Set<string>();
  for (const net of pou.networks)
    for (const el of net.elements)
      if (el.kind === 'coil' && (el.coil === 'M' || el.coil === 'SM' || el.coil === 'RM'))
        out.add(el.variable.trim().toUpperCase());
  return out;
}

/** Variables of the POU written by retentive coils; those not declared in it are globals (added to `globals`). */
function splitRetainedByCoil(pou: Pou, globals: Set<string>): Set<string> {
  const byCoil = retainedByCoil(pou);
  // A VAR_EXTERNAL names a global: its RETAIN goes on the global's declaration.
  const local = new Set(
    [...byCoil].filter((n) =>
      pou.variables.some((v) => v.varClass !== 'external' && v.name.toUpperCase() === n),
    ),
  );
  for (const n of byCoil) if (!local.has(n)) globals.add(n);
  return local;
}

function writePou(w: XmlWriter, pou: Pou, local: ReadonlySet<string>, library: BlockLibrary, marks: readonly string[] = []): void {
  if (pou.language !== 'LD') {
    writeOtherPou(w, pou, marks);
    return;
  }
  w.open('pou', { name: pou.name, pouType: POU_TYPE[pou.kind] }, () => {
    writeInterface(w, pou, local);
    w.open('body', undefined, () => {
      if (!pou.networks.length) {
        w.empty('LD');
        return;
      }
      w.open('LD', undefined, () => {
        let next = 1;
        const ids = { next: () => next++ };
        let top = NETWORK_GAP;
        for (const net of uniqueConnectorNames(pou.networks)) top = writeNetwork(w, net, top, ids, library) + NETWORK_GAP;
      });
    });
    const keep = preserved<PreservedPou>(pou.extensions);
    const addData = [...(keep?.addData ?? []), ...marks];
    if (addData.length) w.open('addData', undefined, () => addData.forEach((d) => w.raw(d)));
    if (pou.comment) w.formatted('documentation', pou.comment);
  });
}

/** The project's own blocks a POU calls: its LD boxes and its FB instances (variables of a user FB type). */
function callees(pou: Pou, library: BlockLibrary): Set<string> {
  const out = new Set<string>();
  const add = (name: string) => {
    const callee = library.userPou(name);
    if (callee && callee !== pou) out.add(callee.name.toUpperCase());
  };
  for (const v of pou.variables) add(v.type);
  for (const net of pou.networks) for (const el of net.elements) if (el.kind === 'box') add(el.blockType);
  return out;
}

/**
 * POU order of the export: project order, except that a FUNCTION_BLOCK or FUNCTION comes before
 * the first POU that calls it (declared before use: what a one-pass reader needs; Beremiz and
 * OpenPLC generate a callee on demand, so the order is only a courtesy to them). A cycle (which
 * IEC 61131-3 forbids) keeps project order. Returns indices into `pous`.
 */
export function calleesFirst(pous: readonly Pou[], library: BlockLibrary): number[] {
  const index = new Map(pous.map((p, i) => [p.name.toUpperCase(), i]));
  const calls = pous.map((p) =>
    [...callees(p, library)].map((n) => index.get(n)).filter((i): i is number => i !== undefined),
  );
  const state: (0 | 1 | 2)[] = pous.map(() => 0);
  const out: number[] = [];
  const visit = (i: number) => {
    if (state[i] !== 0) return;
    state[i] = 1;
    for (const c of calls[i]!) visit(c);
    state[i] = 2;
    out.push(i);
  };
  pous.forEach((_, i) => visit(i));
  return out;
}

/** Serialises the project as PLCopen TC6 XML v2.01 (validates against tc6_xml_v201.xsd). */
export function exportPlcopen(project: Project, options: ExportOptions = {}): string {
  const now = isoSeconds(options.now ?? new Date());
  const keep = preserved<PreservedProject>(project.extensions);
  const w = new XmlWriter();
  const ns: Record<string, string> = {
    xmlns: TC6_0201,
    'xmlns:xhtml': XHTML_NS,
    'xmlns:xsd': 'http://www.w3.org/2001/XMLSchema',
  };
  for (const [prefix, uri] of Object.entries(keep?.namespaces ?? {}))
    if (!(`xmlns:${prefix}` in ns)) ns[`xmlns:${prefix}`] = uri;
  const library = blockLibrary(project);
  const libraries = project.libraries ?? [];
  const globalsByCoil = new Set<string>();
  const localByCoil = project.pous.map((pou) => splitRetainedByCoil(pou, globalsByCoil));
  // Globals go back where the file declared them: the resource's or the configuration's globalVars.
  const resourceGlobals = project.globals.filter((v) => v.scope === 'resource');
  // Under openplc, each POU declares the globals it uses as VAR_EXTERNAL (MATIEC needs them), and
  // records which it added so the import drops them again (addedExternals.ts).
  const withExternals = (pou: Pou, marks: readonly string[]): { pou: Pou; marks: readonly string[] } => {
    const added = needsExternals(project.profile) ? missingExternals(pou, project.globals) : [];
    return added.length
      ? { pou: { ...pou, variables: [...pou.variables, ...added] }, marks: [...marks, externalsMark(added)] }
      : { pou, marks };
  };
  const configurationGlobals = project.globals.filter((v) => v.scope !== 'resource');
  w.open('project', ns, () => {
    w.empty('fileHeader', {
      companyName: 'Rungsmith',
      productName: project.name || 'Untitled',
      productVersion: '1',
      creationDateTime: now,
    });
    w.open('contentHeader', { name: project.name || 'Untitled', modificationDateTime: now }, () => {
      if (project.description) w.leaf('Comment', project.description);
      w.open('coordinateInfo', undefined, () => {
        for (const lang of ['fbd', 'ld', 'sfc'])
          w.open(lang, undefined, () => w.empty('scaling', { x: SCALING, y: SCALING }));
      });
    });
    w.open('types', undefined, () => {
      // The libraries' data types and POUs are written as the project's own (other tools compile
      // them), the POUs marked and the libraries listed in addData (rungsmithData.ts).
      writeDataTypes(w, [...(project.dataTypes ?? []), ...libraries.flatMap((l) => l.dataTypes ?? [])], keep?.dataTypes ?? [], writeType);
      w.open('pous', undefined, () => {
        const libraryPous = libraries.flatMap((l) => l.pous.map((pou) => ({ pou, mark: libraryMark(l.name) })));
        for (const i of calleesFirst(libraryPous.map((l) => l.pou), library)) {
          const { pou, mark } = libraryPous[i]!;
          const local = splitRetainedByCoil(pou, globalsByCoil);
          const out = withExternals(pou, [mark]);
          writePou(w, out.pou, local, library, out.marks);
        }
        for (const i of calleesFirst(project.pous, library)) {
          const out = withExternals(project.pous[i]!, []);
          writePou(w, out.pou, localByCoil[i]!, library, out.marks);
        }
        const names = new Set(project.pous.map((p) => p.name.toUpperCase()));
        for (const raw of keep?.otherPous ?? [])
          if (!names.has((/<pou\s[^>]*name="([^"]*)"/.exec(raw)?.[1] ?? '').toUpperCase())) w.raw(raw);
      });
    });
    w.open('instances', undefined, () =>
      w.open('configurations', undefined, () =>
        w.open('configuration', { name: keep?.configuration || 'Config0' }, () => {
          w.open('resource', { name: keep?.resource || 'Res0' }, () => {
            project.tasks.forEach((t) =>
              w.open(
                'task',
                // Schema order: name, single, interval, priority; an event task may have no interval.
                { name: t.name, single: t.single, interval: t.cycleMs > 0 ? formatInterval(t.cycleMs) : undefined, priority: t.priority },
                () => {
                  for (const p of t.programs) w.empty('pouInstance', { name: p.instance, typeName: p.pou });
                },
              ),
            );
            if (resourceGlobals.length) writeVarLists(w, resourceGlobals, globalsByCoil, true);
          });
          if (configurationGlobals.length) writeVarLists(w, configurationGlobals, globalsByCoil, true);
        }),
      ),
    );
    // The profile the project runs under, so that importing this file gives it back (profileChoice.ts).
    w.open('addData', undefined, () => {
      keep?.addData?.forEach((d) => w.raw(d));
      w.raw(profileData(project.profile));
      if (libraries.length) w.raw(librariesData(libraries));
      if (project.scenarios?.length) w.raw(scenariosData(project.scenarios));
      if (project.plant) w.raw(plantData(project.plant));
    });
  });
  return `<?xml version="1.0" encoding="utf-8"?>\n${w.toString()}`;
}
