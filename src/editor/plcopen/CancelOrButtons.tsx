// The buttons of the PLCopen dialogs: Cancel, then the primary action.
export function CancelOr(props: {
  readonly label: string;
  readonly onCancel: () => void;
  readonly onConfirm: () => void;
  readonly disabled?: boolean;
}) {
  return (
    <>
      <button type="button" className="rs-button" onClick={props.onCancel}>
        Cancel
      </button>
      <button
        type="button"
        className="rs-button rs-primary"
        autoFocus
        disabled={props.disabled}
        onClick={props.onConfirm}
      >
        {props.label}
      </button>
    </>
  );
}
