// The binned SAH builder on several threads. Nodes larger than a threshold are split level by level,
// each level's binning and partitioning spread over the threads; the subtrees below the threshold are
// then built whole, one thread job each, and spliced into the depth-first node array. Every node is
// split by the same steps (binned_sah_split.h, and large_prim_planes.h for the exact planes at large
// primitives, whose passes are chunked as binning is) on the same primitives in the same order,
// whichever thread runs them, and partial bins and bounds are merged in index order (min and max keep
// the first of equal values, so even the sign of a zero is as one pass would give it): the tree is the
// same, bit for bit, for any thread count.
#include <algorithm>
#include <optional>
#include <thread>

#include "bvh/binned_sah_split.h"
#include "bvh/parallel_for.h"

namespace fp {
namespace {

using detail::Bin;
using detail::BinnedSah;
using detail::LargePrims;
using detail::NodeMapping;
using detail::parallelFor;
using detail::PlaneChoice;
using detail::PrimRef;
using detail::RangeBounds;
using detail::SlotMapping;

// Subtrees of at most max(kMinSubtree, n / (threads * kJobsPerThread)) primitives are thread jobs: enough
// jobs to balance the threads, few enough levels above them.
constexpr uint32_t kMinSubtree = 4096;
constexpr uint32_t kJobsPerThread = 16;
// Large nodes are binned and bounded in chunks of this many primitives, one thread job each.
constexpr uint32_t kChunk = 16384;

struct Range {
    uint32_t begin, end;
};

// The ranges cut into chunks of at most kChunk, in order: chunks of one range are consecutive.
struct Chunk {
    size_t range;
    uint32_t begin, end;
};
std::vector<Chunk> chunksOf(const std::vector<Range>& ranges) {
    std::vector<Chunk> chunks;
    for (size_t r = 0; r < ranges.size(); ++r)
        for (uint32_t b = ranges[r].begin; b < ranges[r].end; b += std::min(kChunk, ranges[r].end - b))
            chunks.push_back({r, b, b + std::min(kChunk, ranges[r].end - b)});
    return chunks;
}

std::vector<RangeBounds> parallelRangeBounds(const PrimRef* refs, const std::vector<Range>& ranges,
                                             int threads) {
    const std::vector<Chunk> chunks = chunksOf(ranges);
    std::vector<RangeBounds> partial(chunks.size());
    parallelFor(threads, chunks.size(),
                [&](size_t c) { partial[c] = detail::rangeBounds(refs, chunks[c].begin, chunks[c].end); });
    std::vector<RangeBounds> out(ranges.size());
    for (size_t c = 0; c < chunks.size(); ++c) {  // in order: see the file comment
        out[chunks[c].range].bounds.grow(partial[c].bounds);
        out[chunks[c].range].centroids.grow(partial[c].centroids);
    }
    return out;
}

// A node of the top of the tree, above the subtree jobs.
struct TopNode {
    Range range;
    RangeBounds rb;        // for nodes split here (not for subtree roots)
    uint32_t left = 0;     // children in the top node list; 0 for leaves and subtree roots
    int32_t subtree = -1;  // >= 0: the root of that subtree job
    uint32_t count() const { return range.end - range.begin; }
};

class ParallelBuild {
  public:
    ParallelBuild(HugePageVector<PrimRef>& refs, const BvhBuildOptions& options, int threads)
        : refs_(refs), options_(options), threads_(threads) {}

    Bvh build(uint32_t subtreeLimit) {
        const auto n = uint32_t(refs_.size());
        top_.push_back({{0, n}, {}, 0, -1});
        std::vector<uint32_t> level{0};
        top_[0].rb = parallelRangeBounds(refs_.data(), {top_[0].range}, threads_)[0];
        while (!level.empty()) level = splitLevel(level, subtreeLimit);
        buildSubtrees();
        return assemble();
    }

  private:
    // Splits the nodes of one level, as detail::buildSubtree would one by one; returns the children that
    // are still above subtreeLimit (with their bounds), and lists the others as subtree jobs.
    std::vector<uint32_t> splitLevel(const std::vector<uint32_t>& level, uint32_t subtreeLimit) {
        const int binCount = options_.binCount;
        std::vector<NodeMapping> mappings;
        std::vector<Range> binned;  // the nodes with a plane to look for
        std::vector<size_t> binnedNode;
        for (size_t i = 0; i < level.size(); ++i) {
            mappings.emplace_back(top_[level[i]].rb, binCount);
            if (!mappings[i].flat()) {
                binned.push_back(top_[level[i]].range);
                binnedNode.push_back(i);
            }
        }
        const std::vector<Chunk> chunks = chunksOf(binned);
        const size_t binsPerSet = 3 * size_t(binCount);
        std::vector<Bin> chunkBins(chunks.size() * binsPerSet);
        parallelFor(threads_, chunks.size(), [&](size_t c) {
            detail::binRange(refs_.data(), chunks[c].begin, chunks[c].end,
                             mappings[binnedNode[chunks[c].range]], &chunkBins[c * binsPerSet], binCount);
        });
        std::vector<PlaneChoice> choices(level.size());
        std::vector<Range> searched;  // the nodes that may have large primitives (large_prim_planes.h)
        std::vector<size_t> searchedNode;
        for (size_t c = 0; c < chunks.size(); ++c) {
            detail::mergeBins(&chunkBins[c * binsPerSet], sah_.bins(), binCount);  // in order
            if (c + 1 == chunks.size() || chunks[c + 1].range != chunks[c].range) {
                const size_t i = binnedNode[chunks[c].range];
                const TopNode& node = top_[level[i]];
                if (detail::searchLargePrims(node.count(), node.rb.bounds.area(), rootArea()) &&
                    detail::mayHoldLargePrim(sah_.bins(), binCount, detail::largePrimMinArea(node.rb))) {
                    searched.push_back(node.range);
                    searchedNode.push_back(i);
                }
                choices[i] = sah_.cheapestPlane(mappings[i]);
            }
        }
        std::vector<std::optional<SlotMapping>> slotMappings(level.size());
        addExactPlanes(level, searched, searchedNode, choices, slotMappings);
        for (size_t i = 0; i < level.size(); ++i)
            choices[i] =
                detail::applyLeafRule(choices[i], top_[level[i]].count(), top_[level[i]].rb, options_);
        std::vector<uint32_t> mids(level.size());
        parallelFor(threads_, level.size(), [&](size_t i) {
            const Range r = top_[level[i]].range;
            if (choices[i].axis < 0)
                mids[i] = r.begin;
            else if (choices[i].exact)
                mids[i] = detail::partitionSlots(refs_.data(), r.begin, r.end, *slotMappings[i], choices[i]);
            else
                mids[i] = detail::partition(refs_.data(), r.begin, r.end, mappings[i], choices[i]);
        });

        std::vector<uint32_t> next;
        std::vector<Range> nextRanges;
        for (size_t i = 0; i < level.size(); ++i) {
            const Range r = top_[level[i]].range;
            uint32_t mid = mids[i];
            if (mid <= r.begin || mid >= r.end) {  // the leaf rule of detail::buildSubtree
                if (r.end - r.begin <= uint32_t(options_.maxLeafSize)) continue;
                mid = r.begin + (r.end - r.begin) / 2;
            }
            top_[level[i]].left = uint32_t(top_.size());
            for (Range child : {Range{r.begin, mid}, Range{mid, r.end}}) {
                TopNode node{child, {}, 0, -1};
                if (child.end - child.begin <= subtreeLimit) {
                    node.subtree = int32_t(subtreeRoots_.size());
                    subtreeRoots_.push_back(uint32_t(top_.size()));
                } else {
                    next.push_back(uint32_t(top_.size()));
                    nextRanges.push_back(child);
                }
                top_.push_back(node);
            }
        }
        const std::vector<RangeBounds> rbs = parallelRangeBounds(refs_.data(), nextRanges, threads_);
        for (size_t i = 0; i < next.size(); ++i) top_[next[i]].rb = rbs[i];
        return next;
    }

    // BinnedSah::choose's search for exact planes at large primitives, for the nodes `searched` (level
    // indices searchedNode) with their chunks on all threads, merged in order as the bins are.
    void addExactPlanes(const std::vector<uint32_t>& level, const std::vector<Range>& searched,
                        const std::vector<size_t>& searchedNode, std::vector<PlaneChoice>& choices,
                        std::vector<std::optional<SlotMapping>>& slotMappings) {
        std::vector<Chunk> chunks = chunksOf(searched);
        std::vector<LargePrims> chunkLarge(chunks.size());
        parallelFor(threads_, chunks.size(), [&](size_t c) {
            const TopNode& node = top_[level[searchedNode[chunks[c].range]]];
            detail::findLargePrims(refs_.data(), chunks[c].begin, chunks[c].end,
                                   detail::largePrimMinArea(node.rb), chunkLarge[c]);
        });
        std::vector<LargePrims> large(searched.size());
        for (size_t c = 0; c < chunks.size(); ++c) large[chunks[c].range].merge(chunkLarge[c]);  // in order

        std::vector<Range> slotted;  // the nodes with large primitives
        std::vector<size_t> slottedNode;
        for (size_t s = 0; s < searched.size(); ++s) {
            if (large[s].count == 0) continue;
            slotMappings[searchedNode[s]].emplace(large[s]);
            slotted.push_back(searched[s]);
            slottedNode.push_back(searchedNode[s]);
        }
        chunks = chunksOf(slotted);
        const size_t slotsPerSet = 3 * size_t(detail::kMaxSlots);
        std::vector<Bin> chunkSlots(chunks.size() * slotsPerSet);
        parallelFor(threads_, chunks.size(), [&](size_t c) {
            detail::slotRange(refs_.data(), chunks[c].begin, chunks[c].end,
                              *slotMappings[slottedNode[chunks[c].range]], &chunkSlots[c * slotsPerSet]);
        });
        std::vector<Bin> slots(slotsPerSet);
        for (size_t c = 0; c < chunks.size(); ++c) {
            detail::mergeBins(&chunkSlots[c * slotsPerSet], slots.data(), detail::kMaxSlots);  // in order
            if (c + 1 == chunks.size() || chunks[c + 1].range != chunks[c].range) {
                const size_t i = slottedNode[chunks[c].range];
                choices[i] = detail::cheaperPlane(choices[i], detail::chooseSlotPlane(slots.data()));
            }
        }
    }

    float rootArea() const { return top_[0].rb.bounds.area(); }

    void buildSubtrees() {
        subtreeNodes_.resize(subtreeRoots_.size());
        std::vector<size_t> largestFirst(subtreeRoots_.size());
        for (size_t s = 0; s < largestFirst.size(); ++s) largestFirst[s] = s;
        std::stable_sort(largestFirst.begin(), largestFirst.end(), [this](size_t a, size_t b) {
            return top_[subtreeRoots_[a]].count() > top_[subtreeRoots_[b]].count();
        });
        parallelFor(threads_, largestFirst.size(), [&](size_t j) {
            const size_t s = largestFirst[j];
            const Range r = top_[subtreeRoots_[s]].range;
            BinnedSah sah(options_, rootArea());
            detail::buildSubtree(refs_.data(), r.begin, r.end, options_, sah, subtreeNodes_[s]);
        });
    }

    // The top nodes and the subtrees in depth-first order, subtree indices offset to their place.
    Bvh assemble() {
        size_t total = 0;
        for (const TopNode& node : top_) total += node.subtree < 0;
        for (const HugePageVector<BvhNode>& nodes : subtreeNodes_) total += nodes.size();
        Bvh bvh;
        bvh.nodes.resize(total);
        std::vector<uint32_t> offsets(subtreeNodes_.size());
        constexpr uint32_t kNoParent = std::numeric_limits<uint32_t>::max();
        struct Visit {
            uint32_t node, parent;  // parent: as in detail::buildSubtree
        };
        std::vector<Visit> stack{{0, kNoParent}};
        uint32_t cursor = 0;
        while (!stack.empty()) {
            const Visit v = stack.back();
            stack.pop_back();
            if (v.parent != kNoParent) bvh.nodes[v.parent].first = cursor;
            const TopNode& node = top_[v.node];
            if (node.subtree >= 0) {
                offsets[node.subtree] = cursor;
                cursor += uint32_t(subtreeNodes_[node.subtree].size());
            } else if (node.left == 0) {
                bvh.nodes[cursor++] = {node.rb.bounds, node.range.begin, node.count()};
            } else {
                bvh.nodes[cursor] = {node.rb.bounds, 0, 0};
                stack.push_back({node.left + 1, cursor});
                stack.push_back({node.left, kNoParent});
                ++cursor;
            }
        }
        parallelFor(threads_, subtreeNodes_.size(), [&](size_t s) {
            BvhNode* out = &bvh.nodes[offsets[s]];
            for (const BvhNode& node : subtreeNodes_[s]) {
                *out = node;
                if (!node.isLeaf()) out->first += offsets[s];
                ++out;
            }
        });
        bvh.primIndex = detail::primIndexOf(refs_);
        return bvh;
    }

    HugePageVector<PrimRef>& refs_;
    const BvhBuildOptions& options_;
    int threads_;
    BinnedSah sah_{options_, 0.0f};       // for the top nodes: their bins are merged here
    std::vector<TopNode> top_;            // top_[0] is the root; children are pushed in pairs
    std::vector<uint32_t> subtreeRoots_;  // top node of each subtree job
    std::vector<HugePageVector<BvhNode>> subtreeNodes_;
};

}  // namespace

int buildThreadCount(const BvhBuildOptions& options) {
    if (options.threadCount > 0) return options.threadCount;
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

Bvh buildBinnedSah(const AabbArray& primBounds, const BvhBuildOptions& options) {
    detail::validateOptions(options, primBounds.size());  // before binCount sizes anything
    Bvh bvh;
    if (primBounds.empty()) return bvh;
    HugePageVector<PrimRef> refs = detail::makePrimRefs(primBounds);
    const auto n = uint32_t(refs.size());
    const int threads = buildThreadCount(options);
    const uint32_t subtreeLimit = std::max(kMinSubtree, n / (uint32_t(threads) * kJobsPerThread));
    if (threads > 1 && n > subtreeLimit) return ParallelBuild(refs, options, threads).build(subtreeLimit);

    // One more pass over the primitives, which the threaded build's root needs anyway.
    BinnedSah sah(options, detail::rangeBounds(refs.data(), 0, n).bounds.area());
    detail::buildSubtree(refs.data(), 0, n, options, sah, bvh.nodes);
    bvh.primIndex = detail::primIndexOf(refs);
    return bvh;
}

}  // namespace fp
