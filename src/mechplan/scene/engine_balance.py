"""Parse an engine scene's ``[balance]`` table into a :class:`BalanceSpec`."""

from __future__ import annotations

from ..i18n import Text
from ..model.engine_balance import BalanceSpec
from .reader import Table

KEYS = ("throw_spacing", "throw_positions", "orders", "counterweight_share",
        "counterweight_radius", "balance_shafts", "rod_offset")


def parse_balance(t: Table, throws: int) -> BalanceSpec:
    """The balancing inputs; ``throws``: the number of crank throws (pins) of the engine."""
    t.check_keys(KEYS)
    if t.has("throw_spacing") and t.has("throw_positions"):
        raise t.error("throw_positions", Text("balance.error.either"))
    positions = None
    if t.has("throw_spacing"):
        a = t.quantity("throw_spacing", "length", required=True, positive=True)
        assert a is not None
        positions = tuple(i * a for i in range(throws))
    elif t.has("throw_positions"):
        raw = t.raw("throw_positions")
        if not isinstance(raw, list) or len(raw) != throws:
            raise t.error("throw_positions", Text("balance.error.positions",
                                                  {"count": throws, "got": repr(raw)}))
        positions = tuple(t.value_quantity(v, f"throw_positions[{i}]", "length")
                          for i, v in enumerate(raw))
    orders = t.raw("orders", 6)
    if not isinstance(orders, int) or isinstance(orders, bool) or not 2 <= orders <= 24:
        raise t.error("orders", Text("balance.error.orders", {"got": repr(orders)}))
    share = t.quantity("counterweight_share", "dimensionless", 0.5)
    assert share is not None
    if not 0.0 <= share <= 1.0:
        raise t.error("counterweight_share", Text("balance.error.share", {"value": share}))
    radius = t.quantity("counterweight_radius", "length", positive=True)
    shafts = t.raw("balance_shafts", False)
    if not isinstance(shafts, bool):
        raise t.error("balance_shafts", Text("balance.error.bool", {"got": repr(shafts)}))
    offset = t.quantity("rod_offset", "length", 0.0, nonnegative=True) or 0.0
    if offset and positions is None:
        raise t.error("rod_offset", Text("layouts.error.rod_offset_spacing"))
    return BalanceSpec(positions, orders, share, radius, shafts, offset)
