// mpiWait: an LD_PRELOAD profiling library (the MPI profiling interface,
// PMPI) that times every blocking MPI call of a run by its call stack:
// where the ranks wait for each other. Not part of the solvers; a tool of
// bench/ (docs/results/blast3D.md, "Where the ranks wait").
//
// Build and use (bench/mpiWait/mpiWait.sh does both):
//   mpicxx -O2 -shared -fPIC -o libmpiWait.so mpiWait.C -ldl
//   MPIWAIT_OUT=prefix mpirun -np 2 -x LD_PRELOAD=$PWD/libmpiWait.so -x MPIWAIT_OUT cellBlastFoam -parallel
// Each rank writes prefix.rank<r>: per call stack the MPI function, the
// number of calls, the seconds inside (MPI_Wtime) and the stack's frames
// (shared object and function, demangled, shortened). MPIWAIT_OUT unset:
// nothing is recorded. bench/mpiWait/summary.py groups the stacks by the
// project's function that made the exchange.

#include <mpi.h>
#include <execinfo.h>
#include <dlfcn.h>
#include <cxxabi.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>
#include <algorithm>
#include <ctime>

namespace
{

struct Stat
{
    int id = -1;
    const char* fn = nullptr;
    long calls = 0;
    double seconds = 0;
    double longest = 0;
    std::vector<void*> frames;
};

bool enabled()
{
    static const int on = std::getenv("MPIWAIT_OUT") ? 1 : 0;
    return on;
}

std::unordered_map<std::string, Stat>& table()
{
    static std::unordered_map<std::string, Stat> t;
    return t;
}

double t0 = 0;

//- The thread's CPU time [s]
double cpuNow()
{
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9*ts.tv_nsec;
}

//- CPU time at the last synchronising call's return [s]
double cpuLastSync = -1;

//- CPU time inside MPI calls since the last synchronising call's return
//  [s] (a blocking MPI_Send of a large message polls until the receiver
//  comes: waiting, not work)
double cpuInMpi = 0;

//- The previous call was MPI_Probe (its MPI_Recv does not wait)
bool afterProbe = false;

//- Per synchronising call, in the order made: the site, the rank's CPU
//  time outside MPI since the previous synchronising call (its work) and
//  the wall time inside the call
struct Event
{
    int site;
    float work;
    float wall;
};
std::vector<Event>& trace()
{
    static std::vector<Event> t;
    return t;
}

const int maxFrames = 24;

//- A call that can wait for another rank: the collectives, the waits and
//  the probes; MPI_Recv after MPI_Probe does not
bool synchronises(const char* fn, const bool probed)
{
    static const char* const nonSync[] =
        {"MPI_Send", "MPI_Bsend", "MPI_Isend", "MPI_Irecv", "MPI_Test"};
    for (const char* n : nonSync)
    {
        if (!std::strcmp(fn, n)) return false;
    }
    return !(probed && !std::strcmp(fn, "MPI_Recv"));
}

void record(const char* fn, const double seconds, const double work)
{
    void* frames[maxFrames];
    // frame 0: record, frame 1: the wrapper
    const int n = backtrace(frames, maxFrames);
    std::string key(fn);
    key.append(reinterpret_cast<const char*>(frames + 2),
               sizeof(void*)*(n > 2 ? n - 2 : 0));
    Stat& s = table()[key];
    if (!s.calls)
    {
        s.id = int(table().size()) - 1;
        s.fn = fn;
        s.frames.assign(frames + 2, frames + (n > 2 ? n : 2));
    }
    ++s.calls;
    s.seconds += seconds;
    s.longest = std::max(s.longest, seconds);
    if (work >= 0)
    {
        trace().push_back({s.id, float(work), float(seconds)});
    }
}

std::string frameName(void* p)
{
    Dl_info info;
    if (!dladdr(p, &info) || !info.dli_fname)
    {
        return "?";
    }
    std::string lib(info.dli_fname);
    lib = lib.substr(lib.rfind('/') + 1);
    std::string fn("?");
    if (info.dli_sname)
    {
        int status = 0;
        char* d = abi::__cxa_demangle(info.dli_sname, nullptr, nullptr, &status);
        fn = status == 0 && d ? d : info.dli_sname;
        std::free(d);
    }
    // the function's name without its argument list (templates make
    // them kilobytes long)
    int depth = 0;
    std::string shortFn;
    for (char c : fn)
    {
        if (c == '(' && depth == 0 && !shortFn.empty()) break;
        if (c == '<') ++depth;
        if (c == '>') --depth;
        if (depth == 0 && c != '>') shortFn += c;
    }
    return lib + "!" + shortFn;
}

void dump()
{
    const char* out = std::getenv("MPIWAIT_OUT");
    if (!out) return;
    int rank = 0;
    PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const std::string file(std::string(out) + ".rank" + std::to_string(rank));
    FILE* f = std::fopen(file.c_str(), "w");
    if (!f) return;
    std::vector<const Stat*> all;
    double total = 0;
    for (const auto& kv : table())
    {
        all.push_back(&kv.second);
        total += kv.second.seconds;
    }
    std::sort(all.begin(), all.end(),
        [](const Stat* a, const Stat* b) { return a->seconds > b->seconds; });
    std::fprintf(f, "# mpiWait rank %d: %.6f s from MPI_Init to MPI_Finalize,"
        " %.6f s inside the recorded MPI calls\n", rank, PMPI_Wtime() - t0, total);
    for (const Stat* s : all)
    {
        std::fprintf(f, "site %d %s calls %ld seconds %.6f longest %.6f\n",
            s->id, s->fn, s->calls, s->seconds, s->longest);
        for (void* p : s->frames)
        {
            // a return address: the call is the byte before
            std::fprintf(f, "    %s\n",
                frameName(static_cast<char*>(p) - 1).c_str());
        }
    }
    std::fclose(f);
    // the synchronising calls in order: int32 site, float32 work [s],
    // float32 wall inside [s]
    FILE* b = std::fopen((file + ".trace").c_str(), "wb");
    if (!b) return;
    for (const Event& e : trace())
    {
        std::fwrite(&e.site, 4, 1, b);
        std::fwrite(&e.work, 4, 1, b);
        std::fwrite(&e.wall, 4, 1, b);
    }
    std::fclose(b);
}

struct Timer
{
    const char* fn;
    double start;
    double cpuStart;
    double work;
    bool sync;
    explicit Timer(const char* f)
    :
        fn(f),
        start(0),
        cpuStart(0),
        work(-1),
        sync(false)
    {
        if (!enabled()) return;
        const bool probed = afterProbe;
        afterProbe = !std::strcmp(f, "MPI_Probe");
        sync = synchronises(f, probed);
        cpuStart = cpuNow();
        if (sync && cpuLastSync >= 0)
        {
            work = cpuStart - cpuLastSync - cpuInMpi;
        }
        start = PMPI_Wtime();
    }
    ~Timer()
    {
        if (!enabled()) return;
        const double wall = PMPI_Wtime() - start;
        const double now = cpuNow();
        if (sync)
        {
            cpuLastSync = now;
            cpuInMpi = 0;
            if (work < 0) work = 0;
        }
        else
        {
            cpuInMpi += now - cpuStart;
        }
        record(fn, wall, work);
    }
};

} // End anonymous namespace


extern "C"
{

int MPI_Init_thread(int* argc, char*** argv, int required, int* provided)
{
    const int r = PMPI_Init_thread(argc, argv, required, provided);
    t0 = PMPI_Wtime();
    return r;
}

int MPI_Init(int* argc, char*** argv)
{
    const int r = PMPI_Init(argc, argv);
    t0 = PMPI_Wtime();
    return r;
}

int MPI_Finalize()
{
    dump();
    return PMPI_Finalize();
}

#define WRAP(NAME, ARGS, CALL) \
int NAME ARGS { Timer t(#NAME); return P##NAME CALL; }

WRAP(MPI_Allreduce, (const void* s, void* r, int n, MPI_Datatype d, MPI_Op o, MPI_Comm c), (s, r, n, d, o, c))
WRAP(MPI_Alltoall, (const void* s, int sn, MPI_Datatype sd, void* r, int rn, MPI_Datatype rd, MPI_Comm c), (s, sn, sd, r, rn, rd, c))
WRAP(MPI_Alltoallv, (const void* s, const int* sn, const int* sdis, MPI_Datatype sd, void* r, const int* rn, const int* rdis, MPI_Datatype rd, MPI_Comm c), (s, sn, sdis, sd, r, rn, rdis, rd, c))
WRAP(MPI_Allgather, (const void* s, int sn, MPI_Datatype sd, void* r, int rn, MPI_Datatype rd, MPI_Comm c), (s, sn, sd, r, rn, rd, c))
WRAP(MPI_Allgatherv, (const void* s, int sn, MPI_Datatype sd, void* r, const int* rn, const int* dis, MPI_Datatype rd, MPI_Comm c), (s, sn, sd, r, rn, dis, rd, c))
WRAP(MPI_Gatherv, (const void* s, int sn, MPI_Datatype sd, void* r, const int* rn, const int* dis, MPI_Datatype rd, int root, MPI_Comm c), (s, sn, sd, r, rn, dis, rd, root, c))
WRAP(MPI_Scatterv, (const void* s, const int* sn, const int* dis, MPI_Datatype sd, void* r, int rn, MPI_Datatype rd, int root, MPI_Comm c), (s, sn, dis, sd, r, rn, rd, root, c))
WRAP(MPI_Bcast, (void* b, int n, MPI_Datatype d, int root, MPI_Comm c), (b, n, d, root, c))
WRAP(MPI_Barrier, (MPI_Comm c), (c))
WRAP(MPI_Probe, (int src, int tag, MPI_Comm c, MPI_Status* st), (src, tag, c, st))
WRAP(MPI_Recv, (void* b, int n, MPI_Datatype d, int src, int tag, MPI_Comm c, MPI_Status* st), (b, n, d, src, tag, c, st))
WRAP(MPI_Send, (const void* b, int n, MPI_Datatype d, int dst, int tag, MPI_Comm c), (b, n, d, dst, tag, c))
WRAP(MPI_Bsend, (const void* b, int n, MPI_Datatype d, int dst, int tag, MPI_Comm c), (b, n, d, dst, tag, c))
WRAP(MPI_Isend, (const void* b, int n, MPI_Datatype d, int dst, int tag, MPI_Comm c, MPI_Request* q), (b, n, d, dst, tag, c, q))
WRAP(MPI_Irecv, (void* b, int n, MPI_Datatype d, int src, int tag, MPI_Comm c, MPI_Request* q), (b, n, d, src, tag, c, q))
WRAP(MPI_Wait, (MPI_Request* q, MPI_Status* st), (q, st))
WRAP(MPI_Waitall, (int n, MPI_Request* q, MPI_Status* st), (n, q, st))
WRAP(MPI_Test, (MPI_Request* q, int* flag, MPI_Status* st), (q, flag, st))

#undef WRAP

} // extern "C"
