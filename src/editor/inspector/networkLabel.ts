// Network labels are jump targets: an identifier or an unsigned integer, unique in the POU.

/** Why `label` cannot label this network, or undefined. Labels are identifiers or unsigned integers, unique in the POU. */
export function labelProblem(label: string, others: readonly string[]): string | undefined {
  const t = label.trim();
  if (t === '') return undefined;
  if (!/^(?:[A-Za-z_][A-Za-z0-9_]*|\d+)$/.test(t))
    return 'a label is an identifier (Start_Motor) or an unsigned integer (100)';
  if (others.some((o) => o.toUpperCase() === t.toUpperCase()))
    return `another network is already labelled ${t}`;
  return undefined;
}
