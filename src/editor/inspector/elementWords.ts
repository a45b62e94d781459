// Element names in a PLC programmer's words, with their IEC symbols.
import type { CoilType, ContactType, LdElement } from '../../model/elements';

export const CONTACT_WORDS: Record<ContactType, string> = {
  NO: 'Normally open contact  -| |-',
  NC: 'Normally closed contact  -|/|-',
  P: 'Positive transition contact  -|P|-',
  N: 'Negative transition contact  -|N|-',
  NOT: 'Inverting contact  -|NOT|-',
};

export const COIL_WORDS: Record<CoilType, string> = {
  COIL: 'Coil  -( )-',
  NEG: 'Negated coil  -(/)-',
  SET: 'Set coil  -(S)-',
  RESET: 'Reset coil  -(R)-',
  M: 'Retentive coil  -(M)-',
  SM: 'Retentive set coil  -(SM)-',
  RM: 'Retentive reset coil  -(RM)-',
  P: 'Positive transition coil  -(P)-',
  N: 'Negative transition coil  -(N)-',
};

export function elementTitle(el: LdElement): string {
  switch (el.kind) {
    case 'link':
      return 'Horizontal link';
    case 'contact':
      return CONTACT_WORDS[el.contact];
    case 'coil':
      return COIL_WORDS[el.coil];
    case 'jump':
      return `Jump  -->>${el.target || 'LABEL'}`;
    case 'return':
      return 'Return  <RETURN>';
    case 'connector':
      return `Connector  >${el.name || 'NAME'}>`;
    case 'continuation':
      return `Continuation  >${el.name || 'NAME'}>`;
    case 'box':
      return `${el.blockType} ${el.instance !== undefined ? 'function block' : 'function'}`;
  }
}
