// One notice of the notice area (NoticeArea.tsx): a line in the layout flow under the tool bar,
// never over a control. Each can be dismissed; the same notice raised again while shown is not
// stacked, it counts (×3).
import { useState, type ReactNode } from 'react';

export interface NoticeProps {
  readonly testId: string;
  /** 'error' for what did not happen (a refused run, a fault); 'info' otherwise. */
  readonly tone: 'info' | 'error';
  /** The notice's words; the same words raised again count as a repeat. */
  readonly text: string;
  /** Changes each time the notice is raised (the store's object for it): a new token with the same text is a repeat. */
  readonly token: unknown;
  /** What Dismiss does in the store; without it, Dismiss hides the notice until it is raised again. */
  readonly onDismiss?: () => void;
  /** More than the text (a list of errors), under it. */
  readonly children?: ReactNode;
}

interface Seen {
  readonly text: string;
  readonly token: unknown;
  readonly count: number;
}

/**
 * What each notice slot (its test id) last showed, kept while it is not shown either: the same words
 * raised again after the condition cleared (an edit refused, undone, redone) still count as a repeat,
 * until the notice is dismissed or other words take the slot.
 */
const lastSeen = new Map<string, Seen>();

function useRepeats(slot: string, text: string, token: unknown): number {
  const before = lastSeen.get(slot);
  let seen = before;
  if (!before || before.token !== token) {
    seen = { text, token, count: before && before.text === text ? before.count + 1 : 1 };
    lastSeen.set(slot, seen);
  }
  return seen!.count;
}

export function Notice({ testId, tone, text, token, onDismiss, children }: NoticeProps) {
  const count = useRepeats(testId, text, token);
  const [hidden, setHidden] = useState<unknown>(undefined);
  if (hidden !== undefined && hidden === token) return null;
  const dismiss = () => {
    lastSeen.delete(testId);
    if (onDismiss) onDismiss();
    else setHidden(token);
  };
  return (
    <div
      className={`rs-notice-item rs-notice-${tone}`}
      role={tone === 'error' ? 'alert' : 'status'}
      data-testid={testId}
      data-count={count}
    >
      <div className="rs-notice-body">
        <span className="rs-notice-text">{text}</span>
        {count > 1 && (
          <span className="rs-notice-count" title={`Raised ${count} times`} data-testid="notice-count">
            ×{count}
          </span>
        )}
        {children}
      </div>
      <button type="button" className="rs-notice-dismiss" aria-label="Dismiss this notice" title="Dismiss this notice" onClick={dismiss}>
        ×
      </button>
    </div>
  );
}
