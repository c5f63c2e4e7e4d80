#pragma once
// How the process's allocator treats freed memory.

namespace clothtrack
{
/// Keeps freed memory in the process for the next allocation instead of handing blocks of 128 kB
/// and more back to the system at each free (glibc's default). Every frame allocates and frees
/// arrays of a few MB; returned, they come back as fresh pages, each a page fault, which cost more
/// than parsing a frame on a virtual machine. Blocks of 64 MB and more are still mapped apart and
/// returned, and up to 256 MB of free memory is kept. For the applications' main(): it sets the
/// allocator of the whole process. Does nothing where the allocator is not glibc's.
void keepFreedMemoryForReuse();

/// Hands the whole free pages the allocator keeps back to the system. Frames of a long sequence
/// come and go on several threads; their freed blocks scatter over the allocator's heaps, where
/// they are kept and fragment, and the process grows with the sequence (350 samba frames: 343 MB
/// free in the heaps at the end of the fit, for 143 MB in use). A few milliseconds: for the end
/// of a stage and every few frames of one. Does nothing where the allocator is not glibc's.
void releaseFreedMemory();
} // namespace clothtrack
