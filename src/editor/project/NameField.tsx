// A name being edited in the project tree (POUs, data types).
import { useState } from 'react';

/** A name being edited in the tree: Enter renames (when `problem` finds none), Escape keeps the old one. */
export function NameField(p: {
  readonly name: string;
  readonly testId: string;
  readonly problem: (text: string) => string | undefined;
  readonly onRename: (text: string) => void;
  readonly onDone: () => void;
}) {
  const [text, setText] = useState(p.name);
  const problem = text.trim() === p.name ? undefined : p.problem(text);
  const commit = () => {
    if (!problem && text.trim() !== p.name) p.onRename(text);
    p.onDone();
  };
  return (
    <span className="rs-tree-rename">
      <input
        autoFocus
        aria-label={`New name for ${p.name}`}
        data-testid={p.testId}
        className="rs-cell-input rs-mono"
        value={text}
        spellCheck={false}
        aria-invalid={problem ? true : undefined}
        onFocus={(e) => e.currentTarget.select()}
        onChange={(e) => setText(e.target.value)}
        onBlur={commit}
        onKeyDown={(e) => {
          e.stopPropagation();
          if (e.key === 'Enter' && !problem) commit();
          else if (e.key === 'Escape') p.onDone();
        }}
      />
      {problem && (
        <span role="alert" className="rs-error-text rs-tree-message">
          {problem}
        </span>
      )}
    </span>
  );
}
