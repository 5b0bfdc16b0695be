# cooperage_lookup_first(TARGET LIBRARY...): the libraries named become the
# first entries of TARGET's DT_NEEDED list, in that order.
#
# Why (issue 20, start-up): the dynamic loader resolves every symbol
# reference by walking the lookup scope in order (the executable, then its
# DT_NEEDED breadth first) until a library defines the symbol, checking each
# library's hash table on the way. OCCT's libraries refer mostly to
# themselves and to TKernel and TKMath (Debian builds them BIND_NOW and
# without -Bsymbolic, so every such reference is looked up at load), and
# those came last in the link order: a `--version` walked 19 libraries per
# lookup on average, 42,500 lookups. Listed by how many lookups each
# library answers, the walk is 5.2 libraries long and `--version` takes
# 30 ms instead of 34 (a STEP mesh run makes 100,000 lookups).
# The order changes which copy of an inline function or template the
# references reach, never the behaviour (those copies are the same code).
function(cooperage_lookup_first target)
  target_link_options(${target} BEFORE PRIVATE "LINKER:--push-state,--no-as-needed" ${ARGN}
                      "LINKER:--pop-state")
endfunction()

# What a process of ours (the command, the Python module) lists first: the
# libraries by how many lookups each answered in a STEP mesh run
# (LD_DEBUG=bindings). Needs CooperageOCCT; the framework target is named
# by a generator expression, so it may be defined later.
set(COOPERAGE_PROCESS_LOOKUP_ORDER
  ${OCCT_TKGeomAlgo_LIBRARY} ${OCCT_TKMath_LIBRARY} ${OCCT_TKBO_LIBRARY} ${OCCT_TKernel_LIBRARY}
  ${OCCT_TKGeomBase_LIBRARY} ${OCCT_TKG3d_LIBRARY} -lstdc++ ${OCCT_TKTopAlgo_LIBRARY}
  ${OCCT_TKShHealing_LIBRARY} ${OCCT_TKBRep_LIBRARY} $<TARGET_FILE:OpenMeshCore>
  ${OCCT_TKG2d_LIBRARY} $<TARGET_FILE:cooperage_framework> ${OCCT_TKPrim_LIBRARY})
