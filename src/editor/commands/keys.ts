// Key specs for shortcuts: 'c', 'shift+c', 'mod+z' (mod = Ctrl, or Cmd on macOS), 'delete', 'arrowleft'.
export interface KeySpec {
  readonly key: string;
  readonly mod: boolean;
  readonly shift: boolean;
  readonly alt: boolean;
}

export function parseKeys(spec: string): KeySpec {
  const parts = spec.toLowerCase().split('+');
  const key = parts[parts.length - 1] === '' ? '+' : parts[parts.length - 1]!;
  return { key, mod: parts.includes('mod'), shift: parts.includes('shift'), alt: parts.includes('alt') };
}

const isMac = () => typeof navigator !== 'undefined' && /Mac|iPhone|iPad/.test(navigator.platform);

/** Does the keyboard event match the spec? Letters compare case-insensitively (Shift is explicit). */
export function matches(
  spec: KeySpec,
  e: Pick<KeyboardEvent, 'key' | 'code' | 'ctrlKey' | 'metaKey' | 'shiftKey' | 'altKey'>,
): boolean {
  const mod = isMac() ? e.metaKey : e.ctrlKey;
  if (mod !== spec.mod || e.altKey !== spec.alt) return false;
  const key = e.key.toLowerCase();
  // Shift changes the key of punctuation ('=' -> '+'), so only check it for letters and named keys.
  const shiftMatters = key.length > 1 || /[a-z]/.test(key);
  if (shiftMatters && e.shiftKey !== spec.shift) return false;
  if (key === spec.key) return true;
  // Layout-independent letters: Ctrl+Z on AZERTY reports the code KeyZ.
  return spec.key.length === 1 && /[a-z]/.test(spec.key) && e.code === `Key${spec.key.toUpperCase()}`;
}

const NAMES: Record<string, string> = {
  arrowleft: '←',
  arrowright: '→',
  arrowup: '↑',
  arrowdown: '↓',
  delete: 'Del',
  backspace: 'Backspace',
  enter: 'Enter',
  escape: 'Esc',
  ' ': 'Space',
};

/** Human text for a key spec: 'Ctrl+Shift+B', 'Shift+C'. */
export function keyLabel(spec: string): string {
  const k = parseKeys(spec);
  const parts: string[] = [];
  if (k.mod) parts.push(isMac() ? '⌘' : 'Ctrl');
  if (k.alt) parts.push('Alt');
  if (k.shift) parts.push('Shift');
  parts.push(
    NAMES[k.key] ?? (k.key.length === 1 ? k.key.toUpperCase() : k.key[0]!.toUpperCase() + k.key.slice(1)),
  );
  return parts.join('+');
}
