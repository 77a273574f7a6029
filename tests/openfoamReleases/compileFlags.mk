#------------------------------------------------------------------------------
# compileFlags.mk - the compile line wmake would use for the project's library
# with an OpenFOAM release's own rules, for tests/checkOpenfoamReleases.sh (which
# has no built OpenFOAM, so no wmake of the release to run).
#
# Reads the release's wmake/rules (compiler, -std, warnings, -O, -DOPENFOAM=<release
# number> and the other GFLAGS) and the project's Make/options preprocessed by cpp with
# the release's GFLAGS, as wmake's makefiles/files does (so its #if OPENFOAM guards take
# the release's branch); the include paths as wmake's makefiles/general puts them.
#
# Usage: make -s -f compileFlags.mk WM_PROJECT_DIR=<release> MAKE_DIR=<folder>/Make \
#             OPTIONS=<preprocessed options, written here> compileLine | sources
#   compileLine  the compiler and its flags (the include paths relative to the folder
#                holding Make/, where wmake compiles)
#   sources      Make/files' sources, preprocessed and filtered as makefiles/files does
#------------------------------------------------------------------------------

# The Debian kit's and a typical user's configuration: 64-bit Linux, GCC, optimised,
# double precision, 32-bit labels (the release's etc/bashrc defaults)
WM_ARCH             ?= linux64
WM_COMPILER         ?= Gcc
WM_COMPILE_OPTION   ?= Opt
WM_PRECISION_OPTION ?= DP
WM_LABEL_SIZE       ?= 32
WM_COMPILE_CONTROL  ?=
WM_PROJECT          := OpenFOAM
WM_OSTYPE           := POSIX
WM_DIR              := $(WM_PROJECT_DIR)/wmake

# As wmake's makefiles/general
LIB_SRC         = $(WM_PROJECT_DIR)/src
EXE_INC         =
LIB_LIBS        =
PROJECT_INC     = \
    -I$(LIB_SRC)/$(WM_PROJECT)/lnInclude \
    -I$(LIB_SRC)/OSspecific/$(WM_OSTYPE)/lnInclude
GENERAL_RULES   = $(WM_DIR)/rules/General
include $(GENERAL_RULES)/general

# Make/options as wmake's makefiles/files preprocesses it (PREFILTER_MAKE_OPTIONS)
$(shell $(CPP) -Ulinux -Uunix $(GFLAGS) $(MAKE_DIR)/options | sed -e 's@   *@ @g' > $(OPTIONS))
include $(OPTIONS)

LIB_HEADER_DIRS = \
    $(EXE_INC) \
    -iquote. \
    -IlnInclude \
    $(PROJECT_INC) \
    $(GINC) \
    $(SYS_INC)

.PHONY: compileLine sources
compileLine:
	@echo $(CC) $(c++FLAGS)

# makefiles/files: the sources are Make/files' lines without macros, comments and blanks
sources:
	@$(CPP) -Ulinux -Uunix $(GFLAGS) $(MAKE_DIR)/files | sed -e '/=/d; /^#/d; /^[ \t]*$$/d; s@[ \t]*$$@@'
