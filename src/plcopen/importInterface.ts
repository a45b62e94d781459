// PLCopen declarations → model variables, and configurations → tasks.
import type { Task, VarClass, Variable } from '../model/project';
import { parseInterval } from './durations';
import { readTypeText, readValueText } from './dataTypes';
import { RS_VARIABLE } from './types';
import { unqualifiedType } from './codesys';
import { child, childrenNamed, deepText, type XmlElement } from './xml/parse';

export type Warn = (message: string, el?: XmlElement) => void;

const CLASS_OF: Record<string, VarClass> = {
  localVars: 'local',
  inputVars: 'input',
  outputVars: 'output',
  inOutVars: 'inOut',
  externalVars: 'external',
  tempVars: 'temp',
  globalVars: 'local',
};

const TYPE_ALIASES: Record<string, string> = { string: 'STRING', wstring: 'WSTRING' };

/**
 * The type text of a `<type>` (or returnType) element. Anonymous arrays, structures, enumerations
 * and subranges become type texts (`ARRAY[0..9] OF INT`, `STRUCT X : INT; END_STRUCT`,
 * `(Idle, Run)`, `INT (0..100)`, plcopen/dataTypes.ts) that the engine resolves like named types.
 */
export function readType(typeEl: XmlElement | undefined, warn: Warn): string {
  const t = typeEl?.children[0];
  if (!t) return 'BOOL';
  if (t.name === 'derived') {
    const name = unqualifiedType(t.attrs.name ?? 'BOOL');
    const indirect = INDIRECT.exec(name.trim());
    if (!indirect) return name;
    // CODESYS writes REFERENCE TO / POINTER TO as a derived type name.
    warn(`a ${indirect[1]!.toUpperCase()} TO type is not supported by Rungsmith; the variable keeps the name of its base type ${indirect[2]!.trim()}`, t);
    return indirect[2]!.trim();
  }
  // <string length="20"/>: STRING[20] (the declared length; values hold up to 126 characters).
  if (TYPE_ALIASES[t.name]) return t.attrs.length ? `${TYPE_ALIASES[t.name]!}[${t.attrs.length}]` : TYPE_ALIASES[t.name]!;
  if (ANONYMOUS.has(t.name)) {
    const text = readTypeText(typeEl, warn);
    if (text !== undefined) return text;
  }
  if (ANONYMOUS.has(t.name) || t.name === 'pointer') {
    warn(`a ${t.name} type is not supported by Rungsmith; the variable keeps the name of its base type`, t);
    const base = descendType(t);
    return base ?? t.name.toUpperCase();
  }
  return t.name.toUpperCase();
}

/** `REFERENCE TO T`, `POINTER TO T` (CODESYS writes them as derived type names). */
export const INDIRECT = /^(REFERENCE|POINTER)\s+TO\s+(.+)$/i;

const ANONYMOUS = new Set(['array', 'struct', 'enum', 'subrangeSigned', 'subrangeUnsigned']);

function descendType(el: XmlElement): string | undefined {
  const base = child(el, 'baseType')?.children[0];
  if (!base) return undefined;
  if (base.name === 'derived') return base.attrs.name;
  return TYPE_ALIASES[base.name] ?? base.name.toUpperCase();
}

function initialValue(v: XmlElement, warn: Warn): string | undefined {
  const iv = child(v, 'initialValue');
  if (!iv) return undefined;
  const simple = child(iv, 'simpleValue');
  if (simple) return simple.attrs.value;
  const structured = readValueText(iv); // [32(0), 30(1)], (X := 1, Y := 2)
  if (structured !== undefined) return structured;
  warn(`the initial value of "${v.attrs.name}" (array or structure) is not supported and was dropped`, iv);
  return undefined;
}

/** Every variable of the var lists under `parent` (an interface, resource or configuration). */
export function readVarLists(parent: XmlElement, warn: Warn, only?: readonly string[]): Variable[] {
  const out: Variable[] = [];
  for (const list of parent.children) {
    const cls = CLASS_OF[list.name];
    if (cls === undefined || (only && !only.includes(list.name))) {
      if (list.name === 'accessVars')
        warn('VAR_ACCESS declarations are not supported and were dropped', list);
      continue;
    }
    const retain = list.attrs.retain === 'true' || list.attrs.persistent === 'true';
    const constant = list.attrs.constant === 'true';
    for (const v of childrenNamed(list, 'variable')) {
      const add = child(v, 'addData');
      const byCoil = add
        ? childrenNamed(add, 'data').some(
            (d) => d.attrs.name === RS_VARIABLE && d.children[0]?.attrs.retainByCoil === 'true',
          )
        : false;
      const doc = child(v, 'documentation');
      const init = initialValue(v, warn);
      out.push({
        name: v.attrs.name ?? '',
        type: readType(child(v, 'type'), warn),
        varClass: cls,
        ...(v.attrs.address ? { location: v.attrs.address } : {}),
        ...(init !== undefined ? { initial: init } : {}),
        retain: retain && !byCoil,
        ...(constant ? { constant: true } : {}),
        comment: doc ? deepText(doc).trim() : '',
      });
    }
  }
  return out;
}

export interface InstancesResult {
  readonly tasks: Task[];
  readonly globals: Variable[];
  readonly configuration?: string;
  readonly resource?: string;
}

/** Tasks and global variables from `instances/configurations`. */
export function readInstances(
  instances: XmlElement | undefined,
  warn: Warn,
  /** The file's PROGRAMs (upper case): CODESYS names a task's program in `name`, `typeName` empty. */
  programNames: ReadonlySet<string> = new Set(),
  /** Resources outside `configurations` (CODESYS: `project/addData/data[.../application]/resource`). */
  more: readonly XmlElement[] = [],
): InstancesResult {
  const tasks: Task[] = [];
  const globals: Variable[] = [];
  let configuration: string | undefined;
  let resource: string | undefined;
  const triggers: { el: XmlElement; single: string }[] = [];
  const configs = instances
    ? childrenNamed(child(instances, 'configurations') ?? instances, 'configuration')
    : [];
  const readResource = (res: XmlElement) => {
    resource ??= res.attrs.name;
    for (const t of childrenNamed(res, 'task')) {
      // An event task (single="StartPulse") runs on its trigger; its interval, if any, only
      // counts in the common tick (MATIEC), so none given is 0.
      const single = t.attrs.single?.trim() || undefined;
      let cycleMs = single ? 0 : 10;
      const interval = t.attrs.interval;
      if (interval) {
        const ms = parseInterval(interval);
        if (ms === undefined || ms <= 0)
          warn(`task ${t.attrs.name}: interval "${interval}" is not a duration; using ${single ? 'none' : '10 ms'}`, t);
        else cycleMs = ms;
      } else if (!single) warn(`task ${t.attrs.name} has neither an interval nor a trigger (single); it runs every 10 ms`, t);
      if (single) triggers.push({ el: t, single });
      const programs = childrenNamed(t, 'pouInstance')
        .map((pi) => {
          const instance = pi.attrs.name ?? '';
          const named = pi.attrs.typeName || pi.attrs.type || '';
          return { instance, pou: named || (programNames.has(instance.toUpperCase()) ? instance : '') };
        })
        .filter((p) => {
          if (!p.pou)
            warn(`task ${t.attrs.name}: program instance "${p.instance}" names no POU; dropped`, t);
          return p.pou && p.instance;
        });
      const priority = Number.parseInt(t.attrs.priority ?? '0', 10);
      tasks.push({
        name: t.attrs.name ?? `task${tasks.length}`,
        cycleMs,
        ...(single ? { single } : {}),
        priority: Number.isFinite(priority) ? priority : 0,
        programs,
      });
    }
    for (const pi of childrenNamed(res, 'pouInstance'))
      warn(`program instance "${pi.attrs.name}" is not attached to a task; it is not run`, pi);
    for (const v of readVarLists(res, warn, ['globalVars'])) globals.push({ ...v, scope: 'resource' });
  };
  for (const conf of configs) {
    configuration ??= conf.attrs.name;
    globals.push(...readVarLists(conf, warn, ['globalVars']));
    for (const res of childrenNamed(conf, 'resource')) readResource(res);
  }
  // CODESYS's export of an application alone: its resource in the project's addData.
  for (const res of more) readResource(res);
  for (const { el, single } of triggers) {
    const g = globals.find((v) => v.name.toUpperCase() === single.toUpperCase());
    if (!g || g.type.trim().toUpperCase() !== 'BOOL')
      warn(
        `task ${el.attrs.name}: its trigger single="${single}" ${g ? `is ${g.type}, not BOOL` : 'names no global variable of the configuration or resource'}; the task cannot run until it names a BOOL global (LD-E20)`,
        el,
      );
  }
  return { tasks, globals, ...(configuration ? { configuration } : {}), ...(resource ? { resource } : {}) };
}
