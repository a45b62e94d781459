// The operand field of one box pin, opened on the canvas beside the pin (Enter on a box, or Tab
// from the box's instance name or another pin). Completion and declare-as-you-type as in every
// name field; Enter commits (one undo step per pin), Tab / Shift+Tab commit and go to the next /
// previous open pin, Escape leaves the operand as it was.
import type { BoxElement } from '../../model/elements';
import type { NetworkId } from '../../model/ids';
import type { Network } from '../../model/project';
import { selectLibrary, useDocument, useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import { tabToField, type EditorContext } from '../commands/editorActions';
import { pinRole } from '../inspector/operands';
import { VariableInput, type CancelReason, type EndKey } from '../inspector/VariableInput';
import { pinSlots, withOperand } from './pinOperands';
import { CELL_H, WIRE_Y } from './geometry';

const FIELD_W = 120;
/** The field's height (content pixels): it sits just above the pin's wire, where the operand is written. */
const FIELD_H = 26;
/** Where the box's pin lines meet its body, from its outer edges (content pixels). */
const PIN_LEAD = 18;

export interface PinOperandEditorProps {
  readonly box: BoxElement;
  readonly network: Network;
  readonly pin: string;
  /** The box's left edge, its width and its top row's top + 4 (screen pixels of the scrolled world). */
  readonly left: number;
  readonly width: number;
  readonly top: number;
  /** Height of the network's rows (pins are this far apart). */
  readonly pitch?: number;
  readonly zoom: number;
  /** Ends editing (moving the cursor past the box when `advance`). */
  readonly close: (advance: boolean) => void;
}

export function PinOperandEditor({ box, network, pin, left, width, top, zoom, close, pitch = CELL_H }: PinOperandEditorProps) {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const library = useDocument(selectLibrary);
  const slot = pinSlots(network, box, library).find((s) => s.pin === pin);
  if (!slot) return null;
  // The pin's signature: a user pin declared with a data type keeps its name (Point) for completion.
  const signature = library.signature(box.blockType);
  const pinSig = signature && [...signature.inputs, ...signature.outputs].find((p) => p.name === pin);
  const ctx: EditorContext = { doc, ui };
  const stillMine = () => {
    const now = ui.getState().editing;
    return now?.element === box.id && now.pin === pin;
  };
  const end = (how: EndKey | CancelReason | undefined) => {
    if (how === 'tab' || how === 'backtab')
      return tabToField(ctx, network.id as NetworkId, box.id, pin, how === 'backtab');
    // A blur that follows a move to another field (the old field going away) ends nothing.
    if (how === 'blur' && !stillMine()) return;
    close(how === 'enter');
  };
  const commit = (text: string, how?: EndKey) => {
    const patch =
      slot.side === 'input'
        ? { inputs: withOperand(box.inputs, pin, text) }
        : { outputs: withOperand(box.outputs, pin, text) };
    doc.getState().updateElement(box.id, patch);
    end(how ?? 'enter');
  };
  const x = slot.side === 'input' ? left + PIN_LEAD * zoom - FIELD_W : left + width - PIN_LEAD * zoom;
  const style = {
    left: Math.max(0, x),
    top: top + (slot.rowOffset * pitch + WIRE_Y - 4 - FIELD_H) * zoom,
    width: FIELD_W,
  };
  const label = `${slot.side === 'input' ? 'Input' : 'Output'} ${pin} of ${box.instance || box.blockType}`;
  return (
    <div className="rs-inline-editor" style={style} data-pin={pin}>
      <VariableInput
        key={pin}
        value={slot.operand}
        role={pinSig ? pinRole(pinSig, slot.side, slot.type) : { kind: 'pin', pinType: slot.type, direction: slot.side }}
        autoFocus
        commitOnBlur={false}
        tabMoves
        aria-label={label}
        data-testid="pin-editor"
        placeholder="???"
        onCommit={commit}
        onCancel={end}
      />
    </div>
  );
}
