"""SPH_SOIL's tools: one LAMMPS runner, the readers of LAMMPS's logs and dumps, the analysis of
the runs, bisection over runs, one module per study and a command line.

From the top of the checkout (the package lives in tools/, so tools/ goes on Python's path;
tools/run_example.sh and ctest set it the same way):

    PYTHONPATH=tools /usr/bin/python3 -m sph_soil --help          # the commands and studies
    PYTHONPATH=tools /usr/bin/python3 -m sph_soil vertical-cut     # a study
    bash tools/run_example.sh slope                                # build, run, plot, measure

The LAMMPS binary: --lmp PATH, else $SPH_SOIL_LMP, else lmp in the build directory of the LAMMPS
release that SPH_SOIL_LAMMPS selects (build/ for the default, newest one, build-<release>/ for
another; BUILD_DIR overrides), as tools/build_dir.sh does for the shell scripts.
"""
