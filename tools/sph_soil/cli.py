"""The command line: python3 -m sph_soil COMMAND [options] (tools/ on Python's path)."""
import argparse
import re

from . import __doc__ as package_doc
from . import examples, regression, structure
from .studies import STUDIES

COMMANDS = [examples, regression, structure] + STUDIES


def summary(module):
    """The first sentence (or the part before a colon) of the module's docstring."""
    paragraph = ' '.join(module.__doc__.strip().split('\n\n')[0].split())
    return re.split(r'(?<=:)\s|(?<=\.)\s(?=[A-Z])', paragraph)[0].rstrip('.:')


def parser():
    p = argparse.ArgumentParser(prog='python3 -m sph_soil', description=package_doc,
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog='Studies: ' + ', '.join(m.COMMAND for m in STUDIES) +
                                       '. python3 -m sph_soil COMMAND --help tells more.')
    commands = p.add_subparsers(dest='command', required=True, metavar='COMMAND')
    for module in COMMANDS:
        sub = commands.add_parser(module.COMMAND, help=summary(module), description=module.__doc__,
                                  formatter_class=argparse.RawDescriptionHelpFormatter)
        module.add_arguments(sub)
        sub.set_defaults(main=module.main)
    return p


def main(argv=None):
    args = parser().parse_args(argv)
    args.main(args)
