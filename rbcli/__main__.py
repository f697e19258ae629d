"""``python -m rbcli``."""

import sys

try:
    from rbcli.cli import main
except KeyboardInterrupt:  # Ctrl-C while starting: nothing was written yet
    sys.exit(130)

if __name__ == "__main__":
    main()
