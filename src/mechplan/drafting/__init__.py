"""Pure drafting: primitives with layer roles, fonts and text metrics, frames and title blocks,
label placement. Nothing here knows mechanics; :mod:`mechplan.sheet` presents a solution with it."""
