"""``python -m mechplan.cli``: the command line."""

from . import main

raise SystemExit(main())
