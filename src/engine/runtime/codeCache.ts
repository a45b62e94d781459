// The factories of generated scan code (`new Function(...DISPATCH_PARAMS, body)`), kept by their
// text. An online change that leaves the shapes of the networks alone (an operand retyped, a
// preset changed: values live in the parameter arrays, not in the code) generates the same
// dispatch functions again: the new PLC calls the factory the running one was made from instead
// of a new one, so the engine neither parses the code again nor warms it up again (its compiled
// machine code is kept with the factory), which was CPU and garbage on the scanning thread
// during the change, and slow first scans of the new program.
// Safe by construction: the key is the whole text and the parameter list is fixed, and a factory
// reads nothing but its parameters (`new Function` code sees only the global scope): calling one
// factory twice gives exactly what two factories of the same text give. Every call makes fresh
// closures over the arguments it is given (the new PLC's memory), so nothing is shared between PLCs.
import { DISPATCH_PARAMS } from '../compile/dispatch';

export type CodeFactory = (...args: unknown[]) => unknown;

/** Characters of code kept at most (least recently used dropped first): a few programs' worth. */
const MAX_CHARS = 16 * 1024 * 1024;

const factories = new Map<string, CodeFactory>();
let chars = 0;

/** The factory for `body` (a body of `new Function(...DISPATCH_PARAMS, body)`): the one made for the same text before, or a new one. */
export function dispatchFactory(body: string): CodeFactory {
  const kept = factories.get(body);
  if (kept) {
    // Most recently used last.
    factories.delete(body);
    factories.set(body, kept);
    return kept;
  }
  const made = new Function(...DISPATCH_PARAMS, body) as CodeFactory;
  factories.set(body, made);
  chars += body.length;
  for (const [text] of factories) {
    if (chars <= MAX_CHARS || text === body) break;
    factories.delete(text);
    chars -= text.length;
  }
  return made;
}

/** How many factories are kept (for tests). */
export function keptFactories(): number {
  return factories.size;
}
