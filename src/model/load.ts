// Loading a project file: schema validation (zod) plus structural checks, with located messages.
import { z } from 'zod';
import { COIL_TYPES, CONTACT_TYPES } from './elements';
import { elementCells } from './factory';
import { POU_LANGUAGES, PROJECT_FORMAT, PROJECT_VERSION, type Project } from './project';

const id = z.string().min(1);
const int = z.number().int();
const nonNeg = int.min(0);
const extensions = z.record(z.string(), z.unknown()).optional();

const placed = { id, row: nonNeg, col: nonNeg, comment: z.string().optional() };
const element = z.discriminatedUnion('kind', [
  z.object({ ...placed, kind: z.literal('link') }).strict(),
  z.object({ ...placed, kind: z.literal('contact'), contact: z.enum(CONTACT_TYPES), variable: z.string() }).strict(),
  z.object({ ...placed, kind: z.literal('coil'), coil: z.enum(COIL_TYPES), variable: z.string() }).strict(),
  z.object({ ...placed, kind: z.literal('jump'), target: z.string() }).strict(),
  z.object({ ...placed, kind: z.literal('return') }).strict(),
  z.object({ ...placed, kind: z.literal('connector'), name: z.string() }).strict(),
  z.object({ ...placed, kind: z.literal('continuation'), name: z.string() }).strict(),
  z
    .object({
      ...placed,
      kind: z.literal('box'),
      blockType: z.string().min(1),
      instance: z.string().optional(),
      executionControl: z.boolean().optional(),
      enOpen: z.boolean().optional(),
      inputCount: int.min(1).max(64).optional(),
      inputs: z.record(z.string(), z.string()),
      outputs: z.record(z.string(), z.string()),
      executionOrder: nonNeg.optional(),
      outputOrders: z.record(z.string(), nonNeg).optional(),
    })
    .strict(),
]);

const variableSchema = z
  .object({
    name: z.string().min(1),
    type: z.string().min(1),
    varClass: z.enum(['local', 'input', 'output', 'inOut', 'external', 'temp']),
    location: z.string().optional(),
    initial: z.string().optional(),
    retain: z.boolean(),
    constant: z.boolean().optional(),
    comment: z.string(),
    scope: z.enum(['configuration', 'resource']).optional(),
  })
  .strict();

const networkSchema = z
  .object({
    id,
    label: z.string().optional(),
    title: z.string(),
    comment: z.string(),
    rows: int.min(1).max(10_000),
    cols: int.min(1).max(1_000),
    elements: z.array(element),
    vlinks: z.array(z.object({ row: nonNeg, boundary: nonNeg }).strict()),
    collapsed: z.boolean().optional(),
    turns: z.record(z.string(), int.min(0)).optional(),
    extensions,
  })
  .strict();

const sfcCodeSchema = z.union([
  z.object({ language: z.literal('ST'), text: z.string() }).strict(),
  z.object({ language: z.literal('LD'), networks: z.array(networkSchema), result: z.string().optional() }).strict(),
  z.object({ language: z.literal('none'), why: z.string() }).strict(),
]);

const sfcSchema = z
  .object({
    steps: z.array(
      z
        .object({
          name: z.string().min(1),
          initial: z.boolean(),
          associations: z.array(
            z
              .object({
                action: z.string().min(1),
                qualifier: z.string().min(1),
                duration: z.string().optional(),
                indicator: z.string().optional(),
              })
              .strict(),
          ),
          localId: z.number().optional(),
        })
        .strict(),
    ),
    transitions: z.array(
      z
        .object({
          from: z.array(z.string()),
          to: z.array(z.string()),
          priority: z.number().int().optional(),
          condition: sfcCodeSchema,
          delayed: z.boolean().optional(),
          localId: z.number().optional(),
        })
        .strict(),
    ),
    actions: z.array(z.object({ name: z.string().min(1), body: sfcCodeSchema }).strict()),
    locals: z.array(z.string().min(1)).optional(),
  })
  .strict();

const pouSchema = z
  .object({
    id,
    name: z.string().min(1),
    kind: z.enum(['PROGRAM', 'FUNCTION_BLOCK', 'FUNCTION']),
    returnType: z.string().optional(),
    language: z.enum(POU_LANGUAGES),
    source: z.string().optional(),
    comment: z.string(),
    variables: z.array(variableSchema),
    networks: z.array(networkSchema),
    sfc: sfcSchema.optional(),
    extensions,
  })
  .strict();

const externalBlockSchema = z
  .object({
    name: z.string().min(1),
    kind: z.enum(['FUNCTION_BLOCK', 'FUNCTION']),
    pins: z.array(
      z
        .object({
          name: z.string().min(1),
          dir: z.enum(['in', 'out', 'inOut']),
          type: z.string().min(1).optional(),
          initial: z.string().optional(),
        })
        .strict(),
    ),
    returnType: z.string().min(1).optional(),
    library: z.string().optional(),
    vendor: z.string().optional(),
    comment: z.string().optional(),
  })
  .strict();

const dim = z.object({ lower: int, upper: int }).strict();
const dataTypeDefSchema = z.discriminatedUnion('kind', [
  z.object({ kind: z.literal('enum'), values: z.array(z.string()) }).strict(),
  z
    .object({
      kind: z.literal('struct'),
      members: z.array(
        z.object({ name: z.string(), type: z.string(), initial: z.string().optional(), comment: z.string().optional() }).strict(),
      ),
    })
    .strict(),
  z.object({ kind: z.literal('array'), dims: z.array(dim), of: z.string() }).strict(),
  z.object({ kind: z.literal('subrange'), base: z.string(), lower: int, upper: int }).strict(),
  z.object({ kind: z.literal('alias'), base: z.string() }).strict(),
]);
/** A user data type (Project.dataTypes); its meaning is checked by dataTypes.ts when it is used. */
const dataTypeSchema = z
  .object({
    name: z.string().min(1),
    def: dataTypeDefSchema,
    initial: z.string().optional(),
    comment: z.string().optional(),
    extensions,
  })
  .strict();

const librarySchema = z
  .object({
    name: z.string().min(1),
    hash: z.string().regex(/^sha256:[0-9a-f]{64}$/, 'a library hash is "sha256:" and 64 hex digits'),
    sourceFile: z.string(),
    addedAt: z.string(),
    origin: z.enum(['plcopen', 'rungsmith']),
    pous: z.array(pouSchema),
    dataTypes: z.array(dataTypeSchema).optional(),
  })
  .strict();

export const projectSchema = z
  .object({
    format: z.literal(PROJECT_FORMAT),
    version: z.literal(PROJECT_VERSION),
    name: z.string(),
    description: z.string(),
    profile: z.enum(['iec', 'openplc']),
    pous: z.array(pouSchema),
    globals: z.array(variableSchema),
    tasks: z.array(
      z
        .object({
          name: z.string().min(1),
          cycleMs: z.number().nonnegative(),
          single: z.string().min(1).optional(),
          priority: int,
          programs: z.array(z.object({ instance: z.string().min(1), pou: z.string().min(1) }).strict()),
        })
        .strict()
        // A cyclic task needs an interval; an event task may have none (it runs on its trigger).
        .refine((t) => t.cycleMs > 0 || t.single !== undefined, {
          path: ['cycleMs'],
          message: 'a cyclic task needs an interval above 0 ms (only an event task, with "single", may have none)',
        }),
    ),
    externalBlocks: z.array(externalBlockSchema).optional(),
    scenarios: z.array(z.object({ name: z.string().min(1), csv: z.string() }).strict()).optional(),
    watch: z.array(z.string().min(1)).optional(),
    dataTypes: z.array(dataTypeSchema).optional(),
    libraries: z.array(librarySchema).optional(),
    onlineChange: z.enum(['edit', 'request']).optional(),
    plant: z.object({ id: z.string().min(1), map: z.record(z.string(), z.string().min(1)).optional() }).strict().optional(),
    extensions,
  })
  .strict();

export interface LoadError {
  /** JSON path to the offending value, e.g. `pous[0].networks[3].elements[2].row`. */
  readonly path: string;
  readonly message: string;
}

export type LoadResult = { ok: true; project: Project } | { ok: false; errors: LoadError[] };

const formatPath = (path: readonly PropertyKey[]): string =>
  path.reduce<string>((acc, k) => (typeof k === 'number' ? `${acc}[${k}]` : acc ? `${acc}.${String(k)}` : String(k)), '') ||
  '(root)';

/** Validates parsed JSON as a project. Never throws. */
export function validateProject(data: unknown): LoadResult {
  if (typeof data === 'object' && data !== null) {
    const d = data as Record<string, unknown>;
    if (d.format !== PROJECT_FORMAT) {
      return { ok: false, errors: [{ path: 'format', message: `not a Rungsmith project (format must be "${PROJECT_FORMAT}")` }] };
    }
    if (typeof d.version === 'number' && d.version > PROJECT_VERSION) {
      return {
        ok: false,
        errors: [{ path: 'version', message: `project format version ${d.version} is newer than this Rungsmith supports (${PROJECT_VERSION})` }],
      };
    }
  }
  const parsed = projectSchema.safeParse(data);
  if (!parsed.success) {
    return { ok: false, errors: parsed.error.issues.slice(0, 20).map((i) => ({ path: formatPath(i.path), message: i.message })) };
  }
  const project = parsed.data as unknown as Project; // ids are branded after validation
  const errors = structuralErrors(project);
  return errors.length ? { ok: false, errors } : { ok: true, project };
}

/** Parses project file text (JSON). Never throws. */
export function loadProject(text: string): LoadResult {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch (e) {
    return { ok: false, errors: [{ path: '(file)', message: `not valid JSON: ${(e as Error).message}` }] };
  }
  return validateProject(data);
}

export const saveProject = (project: Project): string => `${JSON.stringify(project, null, 2)}\n`;

function structuralErrors(project: Project): LoadError[] {
  const errors: LoadError[] = [];
  const pouNames = new Set<string>();
  const ids = new Set<string>();
  const seenId = (value: string, path: string) => {
    if (ids.has(value)) errors.push({ path, message: `duplicate id "${value}"` });
    ids.add(value);
  };
  project.pous.forEach((pou, pi) => {
    const pp = `pous[${pi}]`;
    pou.variables.forEach((v, vi) => {
      if (v.scope !== undefined)
        errors.push({ path: `${pp}.variables[${vi}].scope`, message: `only a global variable has a scope ("${v.name}" is declared in POU "${pou.name}")` });
    });
    seenId(pou.id, `${pp}.id`);
    const key = pou.name.toUpperCase();
    if (pouNames.has(key)) errors.push({ path: `${pp}.name`, message: `duplicate POU name "${pou.name}"` });
    pouNames.add(key);
    pou.networks.forEach((net, ni) => {
      const np = `${pp}.networks[${ni}]`;
      seenId(net.id, `${np}.id`);
      const occupied = new Map<string, number>();
      net.elements.forEach((el, ei) => {
        const ep = `${np}.elements[${ei}]`;
        seenId(el.id, `${ep}.id`);
        for (const c of elementCells(el)) {
          if (c.row >= net.rows || c.col >= net.cols) {
            errors.push({ path: ep, message: `element at row ${el.row}, column ${el.col} lies outside the ${net.rows}x${net.cols} grid` });
            break;
          }
          const k = `${c.row}:${c.col}`;
          const other = occupied.get(k);
          if (other !== undefined) {
            errors.push({ path: ep, message: `cell row ${c.row}, column ${c.col} already holds elements[${other}]` });
            break;
          }
          occupied.set(k, ei);
        }
      });
      net.vlinks.forEach((v, vi) => {
        if (v.row + 1 >= net.rows || v.boundary > net.cols) {
          errors.push({ path: `${np}.vlinks[${vi}]`, message: `vertical link at row ${v.row}, boundary ${v.boundary} lies outside the grid` });
        }
      });
    });
  });
  errors.push(...externalBlockErrors(project));
  errors.push(...libraryErrors(project));
  return errors.slice(0, 50);
}

/** External block names are unique, and so are the pin names of each (an in-out pin is one pin). */
function externalBlockErrors(project: Project): LoadError[] {
  const errors: LoadError[] = [];
  const names = new Set<string>();
  (project.externalBlocks ?? []).forEach((block, bi) => {
    const bp = `externalBlocks[${bi}]`;
    const key = block.name.toUpperCase();
    if (names.has(key)) errors.push({ path: `${bp}.name`, message: `duplicate external block "${block.name}"` });
    names.add(key);
    const pins = new Set<string>();
    block.pins.forEach((pin, pi) => {
      const pinKey = pin.name.toUpperCase();
      if (pins.has(pinKey)) errors.push({ path: `${bp}.pins[${pi}].name`, message: `external block "${block.name}" has the pin "${pin.name}" twice` });
      pins.add(pinKey);
    });
  });
  return errors;
}

/** Library names are unique, and each library's POUs are FUNCTION_BLOCKs or FUNCTIONs of unique names. */
function libraryErrors(project: Project): LoadError[] {
  const errors: LoadError[] = [];
  const names = new Set<string>();
  (project.libraries ?? []).forEach((lib, li) => {
    const lp = `libraries[${li}]`;
    const key = lib.name.toUpperCase();
    if (names.has(key)) errors.push({ path: `${lp}.name`, message: `duplicate library "${lib.name}"` });
    names.add(key);
    const pous = new Set<string>();
    lib.pous.forEach((pou, pi) => {
      if (pou.kind === 'PROGRAM') errors.push({ path: `${lp}.pous[${pi}].kind`, message: `library "${lib.name}" holds the PROGRAM "${pou.name}"; a library holds function blocks and functions` });
      const k = pou.name.toUpperCase();
      if (pous.has(k)) errors.push({ path: `${lp}.pous[${pi}].name`, message: `library "${lib.name}" has the POU "${pou.name}" twice` });
      pous.add(k);
    });
  });
  return errors;
}
