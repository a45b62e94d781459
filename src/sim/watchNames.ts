// A name typed into the watch table or the trend while a configuration runs: its variables are
// named by program instance (`MainInstance.Filling`), so a short name (`Filling`) names nothing.
// It resolves to the one instance path that ends in it, or offers the instance paths to pick from.
// Outside a configuration too, the add field completes names and instance paths as they are typed
// (completeWatchName).

export interface WatchNameChoice {
  /** The name to add: the typed name when the program has it, or the one instance path it is short for. */
  readonly name?: string;
  /** The instance paths the text is (the start of) the short name of, for a completion list. */
  readonly choices: readonly string[];
}

/**
 * Resolves `text` against the readable `names`, given the configuration's program `instances`
 * (none outside a configuration). `limit` caps the completion list.
 */
export function resolveWatchName(
  text: string,
  names: readonly string[],
  instances: readonly string[],
  limit = 8,
): WatchNameChoice {
  const t = text.trim().toUpperCase();
  if (!t) return { choices: [] };
  // Spelt exactly first: names that differ only by case (a machine's `tank.Pump` and `tank.pump`) are both offered.
  const exact = names.find((n) => n === text.trim()) ?? names.find((n) => n.toUpperCase() === t);
  if (exact) return { name: exact, choices: [] };
  if (!instances.length) return { choices: [] };
  const prefixes = instances.map((i) => `${i.toUpperCase()}.`);
  // The part of a name after its instance ("FILLING" of "MAININSTANCE.FILLING"), or undefined.
  const shortOf = (n: string): string | undefined => {
    const u = n.toUpperCase();
    const p = prefixes.find((x) => u.startsWith(x));
    return p ? u.slice(p.length) : undefined;
  };
  const whole: string[] = [];
  const started: string[] = [];
  for (const n of names) {
    const s = shortOf(n);
    if (s === undefined) continue;
    if (s === t) whole.push(n);
    else if (s.startsWith(t)) started.push(n);
  }
  const byName = (a: string, b: string) => a.localeCompare(b);
  const choices = [...whole.sort(byName), ...started.sort(byName)].slice(0, limit);
  return whole.length === 1 ? { name: whole[0]!, choices } : { choices };
}

/** Dots and brackets before the last segment: how deep a name is (`T1.ET` 1, `Conv1.T1.ET` 2, `A[2]` 1). */
const depth = (name: string): number => (name.match(/[.[]/g) ?? []).length;

/**
 * Completions of `text` among the readable `names` as it is typed (the watch list's add field):
 * first the names that start with it (an instance path `Conv1.` lists its members, the direct ones
 * first, then nested ones and array elements), then those with a segment that starts with it
 * (`Motor` finds `Conv1.Motor`), then those that contain it; case-insensitive, the typed name
 * itself left out, at most `limit`.
 */
export function completeWatchName(text: string, names: readonly string[], limit = 12): string[] {
  const t = text.trim().toUpperCase();
  if (!t) return [];
  const starts: string[] = [];
  const segment: string[] = [];
  const contains: string[] = [];
  const typed = text.trim();
  // The typed name itself is left out; a name spelt otherwise (`tank.Pump` for `tank.pump`) is another name.
  const spelt = names.filter((n) => n.toUpperCase() === t);
  for (const n of names) {
    const u = n.toUpperCase();
    if (u === t && (n === typed || spelt.length === 1)) continue;
    if (u.startsWith(t)) starts.push(n);
    else if (u.split(/[.[]/).some((s, i) => i > 0 && s.startsWith(t))) segment.push(n);
    else if (u.includes(t)) contains.push(n);
  }
  const byDepth = (a: string, b: string) => depth(a) - depth(b) || a.localeCompare(b, undefined, { numeric: true });
  return [...starts.sort(byDepth), ...segment.sort(byDepth), ...contains.sort(byDepth)].slice(0, limit);
}
