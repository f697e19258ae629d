"""``python -m rbcli``."""

from rbcli.cli import main

if __name__ == "__main__":
    main()
