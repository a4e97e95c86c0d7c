"""Every operation by name, as ``Op.CIRCLE_CIRCLE`` (``from mechplan.construct.ops import Op``).

The families' op constants (each family module's ``__all__``), gathered in one namespace; nothing
is listed here, so adding an operation to a family adds it here.
"""

from __future__ import annotations

from .acceleration import *
from .centre_velocity import *
from .driver_inputs import *
from .drivers import *
from .force import *
from .inputs import *
from .position import *
from .triad import *
from .velocity import *
