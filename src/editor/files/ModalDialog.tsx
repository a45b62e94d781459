// The app's modal dialog: a dimmed backdrop, a titled box and a row of buttons. Keys pressed in it
// stay in it (no editor shortcut acts behind it), so does the focus; Escape closes it (useModal).
import type { ReactNode } from 'react';
import { useModal } from '../layout/useModal';
import './modal.css';

export interface ModalDialogProps {
  /** "alertdialog" for questions and errors that need an answer; "dialog" otherwise. */
  readonly role: 'dialog' | 'alertdialog';
  /** id of the heading, which names the dialog. */
  readonly titleId: string;
  readonly title: ReactNode;
  /** id of the element in `children` that describes the dialog, if one does. */
  readonly describedBy?: string;
  readonly className?: string;
  readonly testId?: string;
  /** What Escape does. */
  readonly onClose: () => void;
  readonly buttons: ReactNode;
  readonly children: ReactNode;
}

export function ModalDialog(props: ModalDialogProps) {
  const modal = useModal(props.onClose);
  return (
    <div className="rs-modal-backdrop">
      <div
        {...modal}
        className={props.className ? `rs-modal ${props.className}` : 'rs-modal'}
        role={props.role}
        aria-modal="true"
        aria-labelledby={props.titleId}
        aria-describedby={props.describedBy}
        data-testid={props.testId}
      >
        <h2 id={props.titleId}>{props.title}</h2>
        {props.children}
        <div className="rs-modal-buttons">{props.buttons}</div>
      </div>
    </div>
  );
}

/** The single button of a dialog that only reports something. */
export function OkButton({ onClick }: { readonly onClick: () => void }) {
  return (
    <button type="button" className="rs-button rs-primary" autoFocus onClick={onClick}>
      OK
    </button>
  );
}
