"""One module per study: what it runs (its run matrix, declared once), how it measures and what it
draws. Each has COMMAND (its name on the command line), add_arguments(parser) and main(args); a
study of one example also has report_example(directory, log, variables, seconds), which
tools/run_example.sh calls on the example's single run to leave its plot and numbers beside it.
convergence_checks.py, the checks that the convergence study runs, is not a study itself."""
from . import (aluminium_bars, atom_style, bearing_capacity, convergence, elastic_column, footing, gate,
               landslide, levels, refine_map, refinement, resolution, retaining_wall, showcase, sliding_block,
               soil_collapse, strength_reduction, vertical_cut)

STUDIES = [aluminium_bars, atom_style, bearing_capacity, convergence, elastic_column, footing, gate, landslide,
           levels, refinement, refine_map, resolution, retaining_wall, showcase, sliding_block, soil_collapse,
           strength_reduction, vertical_cut]

# example (examples/NAME/in.NAME) -> the study that measures and plots its single run
EXAMPLE_REPORTS = {'aluminium_bars': aluminium_bars, 'atom_style': atom_style,
                   'bearing_capacity': bearing_capacity, 'elastic_column': elastic_column, 'footing': footing,
                   'gate': gate, 'landslide_3d': landslide,
                   'shallow_landslide': landslide,
                   'refinement': refinement, 'retaining_wall': retaining_wall, 'sliding_block': sliding_block,
                   'slope': strength_reduction,
                   'soil_collapse': soil_collapse, 'vertical_cut': vertical_cut}
