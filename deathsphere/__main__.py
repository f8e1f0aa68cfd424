"""``python -m deathsphere``: the same CLI as the ``deathsphere`` script."""

from deathsphere.cli import main

if __name__ == "__main__":
    main()
