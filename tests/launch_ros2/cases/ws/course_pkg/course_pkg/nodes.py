"""Entry points the launch files name; never run by the conformance test (it compares argv only)."""


def main() -> None:
    """Does nothing: the launch files are what is compared."""
