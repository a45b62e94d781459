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

export function Notice({ testId, tone, text, token, onDismiss, children }: NoticeProps) {
  const [seen, setSeen] = useState<Seen>({ text, token, count: 1 });
  const [hidden, setHidden] = useState<unknown>(undefined);
  // Raised again: the same words count, other words start over (state adjusted while rendering).
  if (seen.token !== token) setSeen({ text, token, count: seen.text === text ? seen.count + 1 : 1 });
  if (hidden !== undefined && hidden === token) return null;
  const dismiss = () => {
    setSeen({ text, token, count: 0 });
    if (onDismiss) onDismiss();
    else setHidden(token);
  };
  return (
    <div
      className={`rs-notice-item rs-notice-${tone}`}
      role={tone === 'error' ? 'alert' : 'status'}
      data-testid={testId}
      data-count={seen.count}
    >
      <div className="rs-notice-body">
        <span className="rs-notice-text">{text}</span>
        {seen.count > 1 && (
          <span className="rs-notice-count" title={`Raised ${seen.count} times`} data-testid="notice-count">
            ×{seen.count}
          </span>
        )}
        {children}
      </div>
      <button type="button" className="rs-notice-dismiss" aria-label={`Dismiss: ${text}`} title="Dismiss" onClick={dismiss}>
        ×
      </button>
    </div>
  );
}
