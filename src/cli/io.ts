// What the command touches outside itself, injected so tests run it in memory.
export interface CliIo {
  readonly out: (text: string) => void;
  readonly err: (text: string) => void;
  readonly readFile: (path: string) => string;
  readonly writeFile: (path: string, text: string) => void;
}

/** An error the user caused (bad arguments, unreadable file): printed to stderr, exit code 2. */
export class UsageError extends Error {}
