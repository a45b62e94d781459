#!/usr/bin/env node
// The `rungsmith` command (check, simulate, export, import); see docs/cli.md.
// The command is TypeScript; tsx's loader runs it from a clone without a separate compile step.
import { register } from 'tsx/esm/api';

register();
const { runFromNode } = await import(new URL('../src/cli/node.ts', import.meta.url).href);
runFromNode();
