// PLCopen TC6 XML (v2.01, v2.0, legacy v1.0) → a Rungsmith project plus a report of what changed.
// Never throws: bad input gives located errors.
import { newId, type PouId } from '../model/ids';
import { externalInfo, externalSource } from '../model/externalBlocks';
import { blockLibrary, type BlockLibrary } from '../model/library';
import {
  PROJECT_FORMAT,
  PROJECT_VERSION,
  type Pou,
  type PouKind,
  type PouLanguage,
  type Project,
  type DataType,
  type ProjectLibrary,
  type ProjectPlant,
  type Scenario,
  type Task,
  type Variable,
} from '../model/project';
import { readExternalsMark } from './addedExternals';
import { asLibraryPou, readLibrariesData, readLibraryMark, readPlantData, readScenariosData, RS_LIBRARIES, RS_LIBRARY, RS_PLANT, RS_SCENARIOS, type LibraryManifest } from './rungsmithData';
import { importLdBody, type BodyTuning } from './importBody';
import { readInstances, readType, readVarLists } from './importInterface';
import { LdGraphError } from './ldGraph';
import type { Finding } from './ldNodes';
import { pouFingerprint } from './otherPous';
import { unknownBlocks } from './unknownBlocks';
import { readSfcChart } from './sfcChart';
import { upgradeLegacySfc, upgradeLegacyText } from './legacySfc';
import { textLineStarts } from './xml/write';
import { PROFILE_DATA_NAME, chooseProfile } from './profileChoice';
import {
  TC6_0200,
  TC6_0201,
  TC6_V10,
  XHTML_NS,
  type ImportIssue,
  type ImportReport,
  type ImportResult,
  type PreservedPou,
  type PreservedProject,
} from './types';
import {
  child,
  childrenNamed,
  deepText,
  lineLocator,
  parseXml,
  XmlSyntaxError,
  type XmlElement,
} from './xml/parse';
import { readDataTypes } from './dataTypes';
import { applicationDataTypes, applicationPous, applicationResources, cfcOf, CODESYS_APPLICATION, CODESYS_OBJECT_ID, standardPinAliases, utilBlocksUsed, utilNameClashes } from './codesys';
import { blockSignature } from '../model/blocks';
import { isCodesysUtilName } from '../model/codesysUtil';

const KIND: Record<string, PouKind> = {
  program: 'PROGRAM',
  functionBlock: 'FUNCTION_BLOCK',
  function: 'FUNCTION',
};
const LANGUAGES = ['LD', 'ST', 'IL', 'FBD', 'SFC'];

/**
 * What reading an FBD body as LD may say without losing anything: an assignment drawn as a MOVE,
 * a source drawn twice. Any other finding (a wire the grid cannot draw, a dropped negation, an
 * unknown block...) keeps the POU in FBD.
 */
const EXACT_FBD: readonly RegExp[] = [/is drawn as a MOVE block/, /: drawn as a MOVE$/, /drawn twice/];

/** A POU read in the first pass: its interface and body language (its body is read in the second). */
interface PouHead {
  readonly el: XmlElement;
  readonly lang: XmlElement;
  readonly pou: Pou;
  readonly addData: string[];
}

class ImportFailure extends Error {
  constructor(readonly issue: ImportIssue) {
    super(issue.message);
  }
}

/** Pin offsets and wire routes: never read (the grid is built from the wiring), yet most of a file. */
const unread = (parent: string, name: string): boolean =>
  name === 'relPosition' || (name === 'position' && parent === 'connection');

/** Reads PLCopen XML text. */
export function importPlcopen(xmlText: string, tuning?: BodyTuning): ImportResult {
  try {
    return importChecked(xmlText, tuning);
  } catch (e) {
    if (e instanceof ImportFailure) return { ok: false, errors: [e.issue] };
    if (e instanceof XmlSyntaxError)
      return { ok: false, errors: [{ line: e.line, message: `not well-formed XML: ${e.message}` }] };
    return { ok: false, errors: [{ message: `the file could not be imported: ${(e as Error).message}` }] };
  }
}

function importChecked(text: string, tuning: BodyTuning | undefined): ImportResult {
  const root = parseXml(text, { skip: unread });
  // Line numbers are only needed for findings: index the lines on first use.
  let locate: ((offset: number) => number) | undefined;
  const lineOf = (offset: number) => (locate ??= lineLocator(text))(offset);
  const raw = (el: XmlElement) => rawElement(text, el);
  const at = (el: XmlElement | undefined) =>
    el
      ? {
          line: lineOf(el.offset),
          element: el.name,
          ...(el.attrs.localId ? { localId: el.attrs.localId } : {}),
        }
      : {};
  const warnings: ImportIssue[] = [];
  const notes: ImportIssue[] = [];
  let currentPou: string | undefined;
  const warn = (message: string, el?: XmlElement) =>
    warnings.push({ ...at(el), ...(currentPou ? { pou: currentPou } : {}), message });

  if (root.name !== 'project') {
    throw new ImportFailure({
      ...at(root),
      message: `not a PLCopen XML file: the root element is <${root.qname}>, expected <project>`,
    });
  }
  const ns = root.attrs.xmlns ?? '';
  if (ns === TC6_V10) warn('legacy PLCopen TC6 v1.0 file: read as v2.01 (as Beremiz does)', root);
  else if (ns === TC6_0200) warn('PLCopen TC6 v2.0 namespace (CODESYS/TwinCAT): read as v2.01', root);
  else if (ns !== TC6_0201) {
    if (ns)
      throw new ImportFailure({
        ...at(root),
        message: `not a PLCopen TC6 file: unknown namespace "${ns}" (expected ${TC6_0201})`,
      });
    warn('the file declares no PLCopen namespace; read as TC6 v2.01', root);
  }
  const fileHeader = child(root, 'fileHeader');
  const contentHeader = child(root, 'contentHeader');
  const producer = [fileHeader?.attrs.companyName, fileHeader?.attrs.productName].filter(Boolean).join(' / ');
  let recordedProfile: string | undefined;
  for (const holder of [root, contentHeader]) {
    const add = holder ? child(holder, 'addData') : undefined;
    for (const d of add ? childrenNamed(add, 'data') : [])
      if (d.attrs.name === PROFILE_DATA_NAME) recordedProfile ??= child(d, 'profile')?.attrs.name ?? '';
  }
  const profile = tuning?.profile
    ? { profile: tuning.profile, reason: `semantics profile ${tuning.profile}, as asked for (--profile)` }
    : chooseProfile({
        namespace: ns,
        ...(fileHeader?.attrs.companyName ? { companyName: fileHeader.attrs.companyName } : {}),
        ...(recordedProfile !== undefined ? { recorded: recordedProfile } : {}),
      });
  // Under openplc the engine runs the ids itself (Beremiz orders instances, not networks, by them):
  // networks follow the drawing. Elsewhere a network's smallest id places it (importBody.ts).
  // Under openplc the networks also keep Beremiz's order of coils where it is not theirs (Network.turns).
  const bodyTuning: BodyTuning = { ...tuning, orderByIds: profile.profile !== 'openplc', turns: profile.profile === 'openplc' };
  const types = child(root, 'types');
  if (!types)
    throw new ImportFailure({ ...at(root), message: 'the <project> has no <types> element (no POUs)' });

  const namespaces: Record<string, string> = {};
  for (const [k, v] of Object.entries(root.attrs)) {
    if (!k.startsWith('xmlns:')) continue;
    const prefix = k.slice(6);
    if (
      v !== XHTML_NS &&
      v !== TC6_0201 &&
      v !== TC6_0200 &&
      v !== TC6_V10 &&
      prefix !== 'xsd' &&
      prefix !== 'xhtml'
    )
      namespaces[prefix] = v;
  }

  const keepProject: { addData: string[]; dataTypes: string[] } = { addData: [], dataTypes: [] };
  // User data types (dataTypes.ts); the ones Rungsmith cannot read are kept raw for export.
  const userTypes = readDataTypes(child(types, 'dataTypes'), warn, raw, applicationDataTypes(root));
  keepProject.dataTypes.push(...userTypes.raw);
  const pous: Pou[] = [];
  const reportPous: { name: string; networks: number; from: string }[] = [];
  // CODESYS writes the application's POUs in the resource's addData (codesys.ts).
  const pouEls = [...childrenNamed(child(types, 'pous') ?? types, 'pou'), ...applicationPous(root)];
  /** CODESYS object ids dropped (one note for all of them). */
  let objectIds = 0;

  /**
   * Imports an LD (or FBD) body. `quiet` collects the findings instead of reporting them (an FBD
   * body is only converted when nothing is lost); a broken reference throws unless quiet.
   */
  const importLd = (
    pouName: string,
    bodyLd: XmlElement,
    from: string,
    library: BlockLibrary,
    quiet?: ImportIssue[],
    variables: readonly Variable[] = [],
    /** The body's notes (connector pairs drawn), for the caller to report once the body is kept. */
    bodyNotes: ImportIssue[] = notes,
  ): Pou['networks'] | undefined => {
    const bools = new Set(variables.filter((v) => v.type.toUpperCase() === 'BOOL').map((v) => v.name.toUpperCase()));
    try {
      const found: ImportIssue[] = [];
      const { networks, notes: drawn } = importLdBody(
        bodyLd,
        raw,
        (f: Finding) => found.push({ ...at(f.obj?.xml), pou: pouName, message: f.message }),
        library,
        bodyTuning,
        (v) => bools.has(v.toUpperCase()),
      );
      // In file order (a large body is read in batches, each reporting as it goes).
      found.sort((a, b) => (a.line ?? Infinity) - (b.line ?? Infinity));
      for (const message of drawn) bodyNotes.push({ ...at(bodyLd), pou: pouName, message });
      if (quiet) {
        quiet.push(...found);
        return networks;
      }
      for (const f of found) warnings.push(f);
      reportPous.push({ name: pouName, networks: networks.length, from });
      return networks;
    } catch (e) {
      if (e instanceof LdGraphError) {
        const issue = { ...at(e.obj?.xml ?? bodyLd), pou: pouName, message: e.message };
        if (quiet) {
          quiet.push(issue);
          return undefined;
        }
        throw new ImportFailure(issue);
      }
      throw e;
    }
  };

  /** POUs marked as a library's block (rungsmithData.ts): POU name (upper case) -> library. */
  const libraryMarks = new Map<string, { pou: string; library: string }>();
  /** VAR_EXTERNAL declarations, checked against the configuration's and resources' globals below. */
  const externals: { pou: string; name: string; type: string; el: XmlElement }[] = [];
  // First pass: every POU's interface, so a body can call a POU declared after it in the file.
  const heads: PouHead[] = pouEls.map((pouEl) => {
    const name = pouEl.attrs.name ?? '';
    currentPou = name;
    const kind = KIND[pouEl.attrs.pouType ?? ''];
    if (!name) throw new ImportFailure({ ...at(pouEl), message: '<pou> without a name' });
    if (!kind)
      throw new ImportFailure({
        ...at(pouEl),
        pou: name,
        message: `POU "${name}" has an unknown pouType "${pouEl.attrs.pouType ?? ''}"`,
      });
    const iface = child(pouEl, 'interface');
    let variables: Variable[] = iface ? readVarLists(iface, warn) : [];
    for (const list of iface ? childrenNamed(iface, 'externalVars') : [])
      for (const v of childrenNamed(list, 'variable'))
        externals.push({
          pou: name,
          name: v.attrs.name ?? '',
          type: readType(child(v, 'type'), () => {}),
          el: v,
        });
    const returnType = kind === 'FUNCTION' ? readType(child(iface ?? pouEl, 'returnType'), warn) : undefined;
    const body = child(pouEl, 'body');
    // A CODESYS CFC body: an empty ST body with the graph in its addData.
    const lang = cfcOf(body) ?? body?.children.find((c) => LANGUAGES.includes(c.name));
    if (!lang)
      throw new ImportFailure({
        ...at(pouEl),
        pou: name,
        message: `POU "${name}" has no body in a known language (LD, ST, IL, FBD, SFC)`,
      });
    const doc = child(pouEl, 'documentation');
    const addData = child(pouEl, 'addData');
    const pouData = addData ? childrenNamed(addData, 'data') : [];
    for (const d of pouData) {
      const mark = readLibraryMark(d);
      // VAR_EXTERNALs Rungsmith's export added for MATIEC: the project did not declare them.
      const added = readExternalsMark(d);
      if (added) variables = variables.filter((v) => !(v.varClass === 'external' && added.has(v.name.toUpperCase())));
      else if (mark !== undefined) libraryMarks.set(name.toUpperCase(), { pou: name, library: mark });
      else if (d.attrs.handleUnknown === 'discard') {
        if (d.attrs.name === CODESYS_OBJECT_ID) objectIds++;
        else warn(`addData "${d.attrs.name}" dropped (handleUnknown="discard")`, d);
      }
    }
    const pou: Pou = {
      id: newId<'PouId'>('p') as PouId,
      name,
      kind,
      ...(returnType ? { returnType } : {}),
      // A CFC body is kept like an FBD body that does not convert (its source says CFC).
      language: (lang.name === 'CFC' ? 'FBD' : lang.name) as PouLanguage,
      comment: doc ? deepText(doc).trim() : '',
      variables,
      networks: [],
    };
    return { el: pouEl, lang, pou, addData: pouData.filter((d) => d.attrs.handleUnknown !== 'discard' && d.attrs.name !== RS_LIBRARY).map(raw) };
  });
  // Blocks of CODESYS's Util library that the simulator runs (model/codesysUtil.ts): library POUs.
  const utilUsed = utilBlocksUsed(heads);
  const libraryPous = utilUsed.map((u) => u.pou);
  for (const { pou: p, firstUse } of utilUsed) {
    currentPou = firstUse.pou;
    warn(
      `${p.name} is a block of CODESYS's Util library that the file calls without declaring it: added as a library POU (ST, read-only, not exported) that runs CODESYS's documented behaviour`,
      firstUse.el,
    );
  }
  for (const clash of utilNameClashes(heads)) {
    currentPou = clash.pou;
    warn(
      `${clash.name} is called with pins of CODESYS Util's ${clash.name} (${clash.pins.join(', ')}); Rungsmith's ${clash.name} is the annex F block of OpenPLC's library (${describePins(clash.name)}), and Util's ${clash.name} is not supported: the wires of those pins are dropped and the call does not do what it does in CODESYS`,
      clash.el,
    );
  }
  const aliases = standardPinAliases(heads);
  if (aliases.length)
    notes.push({ message: `inputs named as in CODESYS's Standard library read as the IEC pins: ${aliases.join(', ')} (export writes the IEC names)` });
  const withLibrary = [...heads.map((h) => h.pou), ...libraryPous];
  // Blocks of no known library become external blocks with the pins the file wires (issue 12 part 5).
  const external = unknownBlocks(heads, blockLibrary({ pous: withLibrary }));
  const externalBlocks = external.blocks;
  const library = blockLibrary({ pous: withLibrary, externalBlocks });
  externalBlocks.forEach((b, i) => {
    currentPou = external.firstUse[i]!.pou;
    warn(
      isCodesysUtilName(b.name)
        ? `block type ${b.name} is a block of CODESYS's Util library that Rungsmith does not run: imported as an external block with the pins the file wires (${b.pins.map((p) => p.name).join(', ') || 'none'}); it is not simulated, its outputs hold their initial values`
        : `block type ${b.name} is neither a standard block, nor a POU of this file, nor a block of a known vendor library: imported as an external block with the pins the file wires (${b.pins.map((p) => p.name).join(', ') || 'none'}); it is not simulated, its outputs hold their initial values`,
      external.firstUse[i]!.el,
    );
  });
  const vendorCalls = new Map<string, typeof external.vendorCalls>();
  for (const c of external.vendorCalls) vendorCalls.set(c.type, [...(vendorCalls.get(c.type) ?? []), c]);
  for (const [type, calls] of vendorCalls) {
    currentPou = calls[0]!.pou;
    warn(
      `${type} (${externalSource(externalInfo(library.userPou(type))!)}) is an external block: it is not simulated, its outputs hold their initial values and can be set from the Watch table (${calls.length} call${calls.length > 1 ? 's' : ''})`,
      calls[0]!.el,
    );
  }
  currentPou = undefined;

  for (const { el: pouEl, lang, pou: head, addData } of heads) {
    const { name } = head;
    currentPou = name;
    const keepAddData: PreservedPou = addData.length ? { addData } : {};
    const withKeep = (p: Pou, keep: PreservedPou): Pou =>
      Object.keys(keep).length ? { ...p, extensions: { plcopen: keep } } : p;
    let networks: Pou['networks'] | undefined;
    /** Why an FBD body stays FBD. */
    let fbdKept: string | undefined;
    if (lang.name === 'LD') networks = importLd(name, lang, 'POU body', library, undefined, head.variables);
    else if (lang.name === 'FBD') {
      // FBD and LD share their graph vocabulary: an FBD body that the grid draws exactly, with
      // nothing dropped, becomes LD; otherwise it stays FBD (kept, not simulated).
      const found: ImportIssue[] = [];
      const drawn: ImportIssue[] = [];
      const tried = importLd(name, lang, 'FBD body', library, found, head.variables, drawn);
      const lost = found.filter((f) => !EXACT_FBD.some((re) => re.test(f.message)));
      if (tried && !lost.length) {
        networks = tried;
        for (const f of found) warnings.push(f);
        notes.push(...drawn);
        reportPous.push({ name, networks: tried.length, from: 'FBD body' });
        warn(`POU "${name}" was converted from FBD to LD (${tried.length} networks, every wire kept)`, pouEl);
      } else {
        const why = lost[0];
        const what = !why
          ? 'its body cannot be read as a graph'
          : /cannot be drawn exactly/.test(why.message)
            ? 'its wiring does not fit the ladder grid exactly'
            : why.message;
        fbdKept = `${what}${why?.line ? ` (line ${why.line})` : ''}`;
      }
    }
    if (networks) pous.push(withKeep({ ...head, language: 'LD', networks }, keepAddData));
    else {
      const legacy = ns === TC6_V10;
      // A legacy v1.0 chart differs from v2.01 only in its text markup and in how a condition is
      // wired (legacySfc.ts): it is rewritten as v2.01, then read, run and exported like one.
      const upgraded = legacy && lang.name === 'SFC' ? upgradeLegacySfc(raw(pouEl)) : undefined;
      const pouXml = upgraded?.pou ?? pouEl;
      const langXml = upgraded?.sfc ?? lang;
      const rawOf = (el: XmlElement) => (upgraded ? el.doc.src.slice(el.offset, el.end) : raw(el));
      const source = lang.name === 'ST' || lang.name === 'IL' ? deepText(lang).replace(/\r\n?/g, '\n') : rawOf(langXml);
      const pou: Pou = {
        ...head,
        source,
        ...(lang.name === 'SFC' && (!legacy || upgraded)
          ? { sfc: readSfcChart(pouXml, langXml, library, (m) => warn(`in the chart of ${name}, ${m}`, pouEl)) }
          : {}),
      };
      const actions = child(pouXml, 'actions');
      const transitions = child(pouXml, 'transitions');
      const keep: PreservedPou = {
        ...keepAddData,
        // v1.0 FBD bodies that do not read as LD differ from v2.01 (blocks): only text bodies and charts are carried over.
        ...(legacy && lang.name !== 'ST' && lang.name !== 'IL' && !upgraded
          ? { legacyBody: true as const }
          : { pou: upgraded ? upgraded.text : legacy ? upgradeLegacyText(raw(pouEl)) : raw(pouEl), fingerprint: pouFingerprint(pou) }),
        ...(actions && (!legacy || upgraded) ? { actions: rawOf(actions) } : {}),
        ...(transitions && (!legacy || upgraded) ? { transitions: rawOf(transitions) } : {}),
      };
      pous.push(withKeep(pou, keep));
      if (keep.pou)
        warn(
          lang.name === 'CFC'
            ? `POU "${name}" is written in CFC (CODESYS): its interface can be called from LD and it is kept unchanged for export, but Rungsmith does not run CFC: its calls cannot run${head.kind === 'PROGRAM' ? ', and a task that runs it runs its other programs without it' : ''}`
            : lang.name === 'FBD'
            ? `POU "${name}" is written in FBD: its interface can be called from LD and it is kept unchanged for export, but Rungsmith cannot run it (read as LD, ${fbdKept ?? 'its body cannot be read as a graph'}): its calls cannot run`
            : upgraded
              ? `POU "${name}" is written in SFC in the legacy v1.0 format: read as v2.01 (the same chart), Rungsmith runs it and exports it in v2.01, but shows it read-only (the editor edits LD)`
              : `POU "${name}" is written in ${lang.name}: Rungsmith runs it and keeps it unchanged for export, but shows it read-only (the editor edits LD)`,
          pouEl,
        );
      else
        warn(
          `POU "${name}" is written in ${lang.name} in the legacy v1.0 format: its interface is kept, but its body cannot be carried into a v2.01 export (exported empty)${fbdKept ? `; read as LD, ${fbdKept}` : ''}`,
          pouEl,
        );
    }
    // The LD of SFC actions and transitions stays inside the chart (Pou.sfc), which runs it.
  }
  currentPou = undefined;
  pous.push(...libraryPous);
  const manifests: LibraryManifest[] = [];
  const scenarios: Scenario[] = [];
  let plant: ProjectPlant | undefined;
  for (const holder of [root, contentHeader]) {
    const add = holder ? child(holder, 'addData') : undefined;
    for (const d of add ? childrenNamed(add, 'data') : []) {
      // Read as the project (codesys.ts), not kept: export writes it as the project's own content.
      if (d.attrs.name === PROFILE_DATA_NAME || (holder === root && d.attrs.name === CODESYS_APPLICATION)) continue;
      // Rungsmith's libraries and scenarios (rungsmithData.ts): read back into the project.
      else if (d.attrs.name === RS_LIBRARIES) manifests.push(...readLibrariesData(d, warn));
      else if (d.attrs.name === RS_SCENARIOS) scenarios.push(...readScenariosData(d));
      else if (d.attrs.name === RS_PLANT) plant = readPlantData(d) ?? plant;
      else if (d.attrs.handleUnknown === 'discard')
        warn(`addData "${d.attrs.name}" dropped (handleUnknown="discard")`, d);
      else keepProject.addData.push(raw(d));
    }
  }
  if (objectIds)
    notes.push({ message: `${objectIds} CODESYS object id${objectIds > 1 ? 's' : ''} (addData "${CODESYS_OBJECT_ID}", handleUnknown="discard") dropped: CODESYS gives the objects new ids when the file is imported again` });
  const inst = readInstances(
    child(root, 'instances'),
    warn,
    new Set(pous.filter((p) => p.kind === 'PROGRAM').map((p) => p.name.toUpperCase())),
    applicationResources(root),
  );
  // A VAR_EXTERNAL names a global of the configuration or a resource (IEC 61131-3 2.4.1.2).
  const globalTypes = new Map(inst.globals.map((g) => [g.name.toUpperCase(), g]));
  for (const x of externals) {
    const g = globalTypes.get(x.name.toUpperCase());
    const issue = (message: string) => warnings.push({ ...at(x.el), pou: x.pou, message });
    if (!g)
      notes.push({
        ...at(x.el),
        pou: x.pou,
        message: `${x.name} is declared outside the file (VAR_EXTERNAL of ${x.pou}); the simulator keeps it as a global ${x.type}, and export writes the file back without it`,
      });
    else if (g.type.toUpperCase() !== x.type.toUpperCase())
      issue(`VAR_EXTERNAL "${x.name}" of POU "${x.pou}" is ${x.type} but the global variable is ${g.type}`);
  }
  let tasks: Task[] = inst.tasks;
  const ldPous = pous.filter((p) => p.language === 'LD');
  const ldNames = new Set(ldPous.map((p) => p.name.toUpperCase()));
  const firstProgram = ldPous.find((p) => p.kind === 'PROGRAM');
  if (!tasks.some((t) => t.programs.some((p) => ldNames.has(p.pou.toUpperCase()))) && firstProgram) {
    tasks = [
      ...tasks,
      {
        name: 'MainTask',
        cycleMs: 10,
        priority: 1,
        programs: [{ instance: 'MainInstance', pou: firstProgram.name }],
      },
    ];
    warn(`no task runs an LD program: added task MainTask (T#10ms) running "${firstProgram.name}"`);
  }
  const keep: PreservedProject = {
    ...(keepProject.addData.length ? { addData: keepProject.addData } : {}),
    ...(keepProject.dataTypes.length ? { dataTypes: keepProject.dataTypes } : {}),
    ...(Object.keys(namespaces).length ? { namespaces } : {}),
    ...(inst.configuration ? { configuration: inst.configuration } : {}),
    ...(inst.resource ? { resource: inst.resource } : {}),
  };
  const split = splitLibraries(pous, userTypes.types, manifests, libraryMarks, (m) => warn(m));
  const project: Project = {
    format: PROJECT_FORMAT,
    version: PROJECT_VERSION,
    name: contentHeader?.attrs.name || fileHeader?.attrs.productName || 'Imported',
    description: contentHeader ? (child(contentHeader, 'Comment')?.text.trim() ?? '') : '',
    profile: profile.profile,
    pous: split.pous,
    globals: inst.globals,
    tasks,
    ...(scenarios.length ? { scenarios } : {}),
    ...(plant ? { plant } : {}),
    ...(externalBlocks.length ? { externalBlocks } : {}),
    ...(split.dataTypes.length ? { dataTypes: split.dataTypes } : {}),
    ...(split.libraries.length ? { libraries: split.libraries } : {}),
    extensions: { plcopen: keep },
  };
  const report: ImportReport = { namespace: ns || '(none)', producer, pous: reportPous, warnings, notes, profileReason: profile.reason };
  return { ok: true, project, report };
}

/**
 * The POUs and data types a Rungsmith export marked as a library's (rungsmithData.ts) go back into
 * that library, with the version its manifest gives; marked POUs of no listed library stay POUs of
 * the project (said in a warning).
 */
function splitLibraries(
  pous: readonly Pou[],
  types: readonly DataType[],
  manifests: readonly LibraryManifest[],
  marks: ReadonlyMap<string, { pou: string; library: string }>,
  warn: (message: string) => void,
): { pous: Pou[]; dataTypes: DataType[]; libraries: ProjectLibrary[] } {
  const byName = new Map(manifests.map((m) => [m.name.toUpperCase(), m]));
  const taken = new Set<Pou | DataType>();
  const libraries: ProjectLibrary[] = [];
  for (const m of manifests) {
    const listed = new Set(m.pous.map((n) => n.toUpperCase()));
    const own = pous.filter((p) => p.kind !== 'PROGRAM' && (marks.get(p.name.toUpperCase())?.library.toUpperCase() === m.name.toUpperCase() || listed.has(p.name.toUpperCase())));
    const typeNames = new Set(m.dataTypes.map((n) => n.toUpperCase()));
    const ownTypes = types.filter((t) => typeNames.has(t.name.toUpperCase()));
    for (const x of [...own, ...ownTypes]) taken.add(x);
    libraries.push({
      name: m.name,
      hash: m.hash,
      sourceFile: m.sourceFile,
      addedAt: m.addedAt,
      origin: m.origin,
      pous: own.map((p) => asLibraryPou(m.name, p)),
      ...(ownTypes.length ? { dataTypes: ownTypes } : {}),
    });
  }
  for (const { pou, library: lib } of marks.values())
    if (!byName.has(lib.toUpperCase()))
      warn(`POU ${pou} is marked as a block of the library ${lib}, which the file does not list: imported as a POU of the project`);
  return { pous: pous.filter((p) => !taken.has(p)), dataTypes: types.filter((t) => !taken.has(t)), libraries };
}

/**
 * The source text of an element, its continuation lines dedented by the element's own indentation
 * (not the lines inside text, e.g. an ST body's CDATA: they are kept as written).
 */
function rawElement(text: string, el: XmlElement): string {
  const lineStart = text.lastIndexOf('\n', el.offset - 1) + 1;
  const lead = text.slice(lineStart, el.offset);
  const indent = /^[ \t]*$/.test(lead) ? lead.length : 0;
  const source = text.slice(el.offset, el.end).replace(/\r\n?/g, '\n');
  const inText = textLineStarts(source);
  const dedent = new RegExp(`^[ \\t]{0,${indent}}`);
  return source
    .split('\n')
    .map((l, i) => (i === 0 || inText[i - 1] ? l : l.replace(dedent, '')))
    .join('\n');
}

/** The pins of a standard block as `XIN1, XIN2, EPS -> Q`. */
function describePins(name: string): string {
  const sig = blockSignature(name);
  return sig ? `${sig.inputs.map((p) => p.name).join(', ')} -> ${sig.outputs.map((p) => p.name).join(', ')}` : '';
}
