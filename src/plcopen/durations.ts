// Task intervals as written by PLC tools: IEC `T#20ms` / `TIME#1s500ms`, CODESYS ISO-8601 `PT0.05S`,
// legacy Beremiz `00:00:00.100000`.

const UNIT_MS: Record<string, number> = {
  d: 86_400_000,
  h: 3_600_000,
  m: 60_000,
  s: 1000,
  ms: 1,
  us: 0.001,
  ns: 0.000001,
};

/** Milliseconds of an interval text, or undefined when it is not a duration. */
export function parseInterval(text: string): number | undefined {
  const t = text.trim();
  const iec = /^(?:T|TIME|LTIME|LT)#(-?)(.+)$/i.exec(t);
  if (iec) {
    let rest = iec[2]!.replace(/_/g, '').toLowerCase();
    let total = 0;
    let any = false;
    while (rest.length) {
      const m = /^(\d+(?:\.\d+)?)(ms|us|ns|d|h|m|s)/.exec(rest);
      if (!m) return undefined;
      total += Number(m[1]) * UNIT_MS[m[2]!]!;
      rest = rest.slice(m[0].length);
      any = true;
    }
    return any ? (iec[1] ? -total : total) : undefined;
  }
  const iso =
    /^P(?:(\d+(?:\.\d+)?)D)?(?:T(?:(\d+(?:\.\d+)?)H)?(?:(\d+(?:\.\d+)?)M)?(?:(\d+(?:\.\d+)?)S)?)?$/i.exec(t);
  if (iso && t.length > 1 && t.toUpperCase() !== 'PT') {
    const [, d, h, m, s] = iso;
    return (Number(d ?? 0) * 86_400 + Number(h ?? 0) * 3600 + Number(m ?? 0) * 60 + Number(s ?? 0)) * 1000;
  }
  const clock = /^(\d+):(\d+):(\d+(?:\.\d+)?)$/.exec(t);
  if (clock) return (Number(clock[1]) * 3600 + Number(clock[2]) * 60 + Number(clock[3])) * 1000;
  return undefined;
}

/** `T#10ms`, `T#1s`, `T#1s500ms`, `T#0.5ms` (compact IEC duration of a millisecond count). */
export function formatInterval(ms: number): string {
  if (!Number.isFinite(ms) || ms <= 0) return 'T#0ms';
  if (!Number.isInteger(ms)) return `T#${Number(ms.toFixed(6))}ms`;
  const parts: string[] = [];
  let rest = ms;
  for (const [unit, size] of [
    ['h', 3_600_000],
    ['m', 60_000],
    ['s', 1000],
  ] as const) {
    if (rest >= size) {
      parts.push(`${Math.floor(rest / size)}${unit}`);
      rest %= size;
    }
  }
  if (rest || !parts.length) parts.push(`${rest}ms`);
  return `T#${parts.join('')}`;
}
