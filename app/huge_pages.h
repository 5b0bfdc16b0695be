// The `cooperage` command's memory tuning (huge_pages.cpp): its operator
// new and heap advice act at start-up; this part depends on the run.
#pragma once

namespace cooperage::app {

/// With two threads or fewer (`requested` as --threads: 0 means every core),
/// every thread allocates from the main heap, which the command advised as
/// transparent huge pages at start-up; otherwise glibc gives a worker thread
/// its own arena, whose pages are not advised. Threads that allocated
/// already keep their arena: call it before the meshing starts its threads
/// (MeshOptions::after_geometry).
void share_heap_when_few_threads(int requested);

}  // namespace cooperage::app
