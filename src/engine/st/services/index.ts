// Language services of the ST editor (issue 25), pure: no DOM, no editor. Every service takes the
// project, the POU (by id) and the body's text as the editor has it, and answers in offsets and
// 1-based lines/columns of that text.
//   stDiagnostics   the compiler's findings for the body, located (diagnostics.ts)
//   stCompletions   completion at an offset (completion.ts)
//   stHover         type, class, initial value and comment; a block's signature (navigate.ts)
//   stDefinition    where a name is declared: a variable's row, a POU, a data type (navigate.ts)
//   planStRename    checks a variable rename from the body; stRenameEdits: the ST bodies it
//                   changes (the store applies them with the declaration and LD uses, rename.ts)
export { stDiagnostics, withBody, type StDiagnostic } from './diagnostics';
export { stCompletions, type StCompletion, type StCompletionResult, type CompletionKind } from './completion';
export { stHover, stDefinition, symbolAt, type StHover, type StDefinition } from './navigate';
export {
  planStRename,
  checkRename,
  stRenameEdits,
  renameInText,
  variableNameProblem,
  type RenamePlan,
} from './rename';
export { readBody, offsetOf, positionOf } from './text';
