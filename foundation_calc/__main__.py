"""``python -m foundation_calc`` runs ``fcalc``."""

from foundation_calc.cli.app import main

main()
