#include "seaflex/io/hdf5_recorder.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "seaflex/core/output_file.hpp"
#include "seaflex/post/envelope.hpp"

namespace seaflex::io {

namespace {

// Crash safety. A compressed chunk that is rewritten (a partly filled chunk flushed after
// every row) changes size and moves; HDF5 would give the old space to the next chunk
// written, which a kill before the next flush leaves under the old index: an unreadable
// file. So no file space is ever reused (file space strategy NONE), rows of at least
// kCompressMinBytes are one compressed chunk each (written once, never rewritten), and
// smaller rows go uncompressed into multi-row chunks, which are rewritten in place.
// Below 16 KiB a row compresses poorly and zlib's set-up per chunk costs more than the
// compression (measured: a third of the run time of bench/riser/riser_n100.yaml at 1 KiB).
constexpr hsize_t kCompressMinBytes = 16 * 1024;
// deflate level 1: double-precision results pack hardly better at higher levels
constexpr unsigned kDeflateLevel = 1;
// an uncompressed chunk holds about this many bytes
constexpr hsize_t kChunkBytes = 16 * 1024;
constexpr hsize_t kMaxChunkRows = 1024;
// the most rows a block holds (Hdf5Recorder::set_work_counter)
constexpr hsize_t kMaxBlockRows = 1024;

// An HDF5 identifier closed by its own close function.
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = o.id_;
      close_ = o.close_;
      o.id_ = -1;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = -1;
  }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

}  // namespace

struct Hdf5Recorder::Impl {
  std::filesystem::path path;
  Handle file;

  // a failure is an OutputError, as for the CSV files: exit code 3, "cannot write PATH: ..."
  // (named once: after a failure the file takes no more writes, flush() included)
  mutable bool failed = false;
  hid_t check(hid_t id, const char* what) const {
    if (id < 0) fail(what);
    return id;
  }
  void check_status(herr_t status, const char* what) const {
    if (status < 0) fail(what);
  }
  [[noreturn]] void fail(const char* what) const {
    failed = true;
    throw OutputError(path, fmt::format("HDF5 {} failed", what));
  }

  // creation properties of a group or dataset without modification times, so that the same
  // run writes the same bytes (batches compare their cases with serial runs byte for byte)
  Handle untimed(hid_t plist_class) const {
    Handle plist(check(H5Pcreate(plist_class), "H5Pcreate"), H5Pclose);
    check_status(H5Pset_obj_track_times(plist.get(), false), "H5Pset_obj_track_times");
    return plist;
  }

  Handle group(hid_t parent, const std::string& name) {
    const Handle gcpl = untimed(H5P_GROUP_CREATE);
    return {
        check(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), "H5Gcreate"),
        H5Gclose};
  }

  void string_attribute(hid_t object, const char* name, const std::string& value) {
    // variable length: h5py reads it as str (a fixed-length string comes back as bytes)
    Handle type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose);
    check_status(H5Tset_size(type.get(), H5T_VARIABLE), "H5Tset_size");
    check_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), "H5Tset_cset");
    Handle space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
    Handle attr(check(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      "H5Acreate"),
                H5Aclose);
    const char* text = value.c_str();
    check_status(H5Awrite(attr.get(), type.get(), &text), "H5Awrite");
  }

  void long_attribute(hid_t object, const char* name, long value) {
    Handle space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
    Handle attr(
        check(H5Acreate2(object, name, H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
              "H5Acreate"),
        H5Aclose);
    const long long v = value;
    check_status(H5Awrite(attr.get(), H5T_NATIVE_LLONG, &v), "H5Awrite");
  }

  // a fixed dataset of doubles (or ints when ints is given), written at once
  void array(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims,
             const double* values, const char* unit) {
    Handle space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                       "H5Screate_simple"),
                 H5Sclose);
    Handle set(check(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                untimed(H5P_DATASET_CREATE).get(), H5P_DEFAULT),
                     "H5Dcreate"),
               H5Dclose);
    check_status(H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values),
                 "H5Dwrite");
    if (unit) string_attribute(set.get(), "units", unit);
  }
  void int_array(hid_t parent, const std::string& name, const std::vector<int>& values) {
    const hsize_t n = values.size();
    Handle space(check(H5Screate_simple(1, &n, nullptr), "H5Screate_simple"), H5Sclose);
    Handle set(check(H5Dcreate2(parent, name.c_str(), H5T_STD_I32LE, space.get(), H5P_DEFAULT,
                                untimed(H5P_DATASET_CREATE).get(), H5P_DEFAULT),
                     "H5Dcreate"),
               H5Dclose);
    check_status(H5Dwrite(set.get(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
                 "H5Dwrite");
  }
  void string_array(hid_t parent, const std::string& name, const std::vector<std::string>& v) {
    Handle type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose);
    check_status(H5Tset_size(type.get(), H5T_VARIABLE), "H5Tset_size");
    check_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), "H5Tset_cset");
    const hsize_t n = v.size();
    Handle space(check(H5Screate_simple(1, &n, nullptr), "H5Screate_simple"), H5Sclose);
    Handle set(check(H5Dcreate2(parent, name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                                untimed(H5P_DATASET_CREATE).get(), H5P_DEFAULT),
                     "H5Dcreate"),
               H5Dclose);
    std::vector<const char*> ptrs;
    for (const auto& s : v) ptrs.push_back(s.c_str());
    if (n > 0)
      check_status(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()),
                   "H5Dwrite");
  }

  // A dataset that grows by one row per output time: dims (rows, shape...).
  struct Series {
    Handle set;
    std::vector<hsize_t> shape;  // of one row
    hsize_t row_size = 1;
    std::vector<double> staged;  // rows not written yet, one after the other
  };
  Series series(hid_t parent, const std::string& name, std::vector<hsize_t> shape,
                const char* unit) {
    Series s;
    s.shape = std::move(shape);
    for (hsize_t d : s.shape) s.row_size *= d;
    const int rank = static_cast<int>(s.shape.size()) + 1;
    std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk;
    const hsize_t row_bytes = std::max<hsize_t>(1, s.row_size * sizeof(double));
    const bool compress = row_bytes >= kCompressMinBytes;
    chunk.push_back(compress ? 1 : std::clamp<hsize_t>(kChunkBytes / row_bytes, 1, kMaxChunkRows));
    for (hsize_t d : s.shape) {
      dims.push_back(d);
      max.push_back(d > 0 ? d : H5S_UNLIMITED);  // a chunk must fit a fixed dimension
      chunk.push_back(std::max<hsize_t>(1, d));
    }
    Handle space(check(H5Screate_simple(rank, dims.data(), max.data()), "H5Screate_simple"),
                 H5Sclose);
    Handle plist = untimed(H5P_DATASET_CREATE);
    check_status(H5Pset_chunk(plist.get(), rank, chunk.data()), "H5Pset_chunk");
    if (compress) {
      check_status(H5Pset_shuffle(plist.get()), "H5Pset_shuffle");
      check_status(H5Pset_deflate(plist.get(), kDeflateLevel), "H5Pset_deflate");
    }
    s.set = Handle(check(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                    plist.get(), H5P_DEFAULT),
                         "H5Dcreate"),
                   H5Dclose);
    if (unit) string_attribute(s.set.get(), "units", unit);
    return s;
  }
  // a row kept in memory until the block it belongs to is written
  static void stage(Series& s, const double* values) {
    s.staged.insert(s.staged.end(), values, values + s.row_size);
  }
  // the rows [written, rows) of a dataset, kept by stage(), in one write
  void write_staged(Series& s) {
    const hsize_t n = rows - written;
    std::vector<hsize_t> dims{rows}, start{written}, count{n};
    for (hsize_t d : s.shape) {
      dims.push_back(d);
      start.push_back(0);
      count.push_back(d);
    }
    check_status(H5Dset_extent(s.set.get(), dims.data()), "H5Dset_extent");
    if (s.row_size == 0) return;
    Handle file_space(check(H5Dget_space(s.set.get()), "H5Dget_space"), H5Sclose);
    check_status(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                     count.data(), nullptr),
                 "H5Sselect_hyperslab");
    // the memory space in the selection's shape: HDF5 then copies whole rows, where a flat
    // one made it map the values one by one
    Handle mem(check(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr),
                     "H5Screate_simple"),
               H5Sclose);
    check_status(H5Dwrite(s.set.get(), H5T_NATIVE_DOUBLE, mem.get(), file_space.get(), H5P_DEFAULT,
                          s.staged.data()),
                 "H5Dwrite");
    s.staged.clear();
  }
  // every staged row on disk, data and metadata: a run killed after this keeps them
  void write_rows();

  struct Beam {
    post::BeamResults results;
    post::Envelope envelope;
    Handle group;
    Series positions;
    std::vector<Series> quantities;  // per output row (empty unless per_row)
    bool envelope_written = false;
  };
  std::function<Hdf5Recorder::Table()> statistics;
  bool statistics_written = false;
  std::vector<post::BeamResults> pending;  // until begin()
  std::vector<Beam> beams;
  bool per_row = true, envelope = true;
  bool envelope_steps = false;  // the envelopes' extremes over every step
  Series time, channels;
  hsize_t rows = 0;              // rows recorded
  hsize_t written = 0;           // rows on disk
  std::function<double()> work;  // set_work_counter()
  double work_written = 0.0;     // work() at the last write
  MatX table;
  std::vector<double> buffer;
};

void Hdf5Recorder::Impl::write_rows() {
  if (written == rows) return;
  write_staged(time);
  write_staged(channels);
  for (auto& b : beams) {
    write_staged(b.positions);
    for (auto& q : b.quantities) write_staged(q);
  }
  written = rows;
  if (work) work_written = work();
  check_status(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "H5Fflush");
}

Hdf5Recorder::Hdf5Recorder(const std::filesystem::path& path, std::vector<post::BeamResults> beams,
                           bool per_row, bool envelope, bool envelope_steps)
    : impl_(std::make_unique<Impl>()) {
  // no HDF5 clean-up at exit (before the library's first use): a file whose writes failed (a
  // full disk, a file size limit) cannot be closed, and the library's exit handler then
  // crashed on it (H5F__close_cb, a segmentation fault after the error was reported). The
  // rows flushed so far are on disk either way; a file closed normally is closed here.
  static const bool no_atexit = H5dont_atexit() >= 0;
  (void)no_atexit;
  impl_->path = path;
  impl_->pending = std::move(beams);
  impl_->per_row = per_row;
  impl_->envelope = envelope;
  impl_->envelope_steps = envelope && envelope_steps;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr
  // the default (earliest) file format where it suffices (the file space strategy needs
  // HDF5 1.10 to read): no "open for writing" flag that would make a file left by a
  // killed run unreadable without h5clear
  Handle fcpl(impl_->check(H5Pcreate(H5P_FILE_CREATE), "H5Pcreate"), H5Pclose);
  impl_->check_status(H5Pset_file_space_strategy(fcpl.get(), H5F_FSPACE_STRATEGY_NONE, 0, 1),
                      "H5Pset_file_space_strategy");
  impl_->file = Handle(
      impl_->check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), "H5Fcreate"),
      H5Fclose);
}

Hdf5Recorder::~Hdf5Recorder() = default;

void Hdf5Recorder::begin(const std::vector<std::string>& channels) {
  Impl& m = *impl_;
  const hid_t root = m.file.get();
  m.string_attribute(root, "format", "seaflex results 1");
  m.time = m.series(root, "time", {}, "s");
  m.channels = m.series(root, "channels", {channels.size()}, nullptr);
  m.string_array(root, "channel_names", channels);
  Handle beams = m.group(root, "beams");
  for (auto& r : m.pending) {
    const AncfBeam& b = r.beam();
    Impl::Beam beam{std::move(r), {}, m.group(beams.get(), b.name()), {}, {}, false};
    const hid_t g = beam.group.get();
    m.long_attribute(g, "elements", b.num_elements());
    std::vector<double> node_s;
    for (int k = 0; k < b.num_nodes(); ++k) node_s.push_back(b.node_arc_length(k));
    m.array(g, "node_s", {node_s.size()}, node_s.data(), "m");
    beam.positions = m.series(g, "positions", {static_cast<hsize_t>(b.num_nodes()), 3}, "m");
    const auto& st = beam.results.stations();
    std::vector<double> s, xi;
    std::vector<int> element, node;
    for (const auto& p : st) {
      s.push_back(p.s);
      xi.push_back(p.xi);
      element.push_back(p.element);
      node.push_back(p.node);
    }
    Handle stations = m.group(g, "stations");
    m.array(stations.get(), "s", {s.size()}, s.data(), "m");
    m.array(stations.get(), "xi", {xi.size()}, xi.data(), nullptr);
    m.int_array(stations.get(), "element", element);
    m.int_array(stations.get(), "node", node);
    if (m.per_row) {
      Handle results = m.group(g, "results");
      for (const auto& q : post::beam_quantities())
        beam.quantities.push_back(
            m.series(results.get(), std::string(q.name), {st.size()}, std::string(q.unit).c_str()));
    }
    m.beams.push_back(std::move(beam));
  }
  m.pending.clear();
  m.check_status(H5Fflush(root, H5F_SCOPE_GLOBAL), "H5Fflush");
}

void Hdf5Recorder::record(const State& state, std::span<const double> values) {
  Impl& m = *impl_;
  m.stage(m.time, &state.t);
  m.stage(m.channels, values.data());
  for (auto& b : m.beams) {
    const AncfBeam& beam = b.results.beam();
    m.buffer.resize(3 * static_cast<std::size_t>(beam.num_nodes()));
    for (int k = 0; k < beam.num_nodes(); ++k)
      for (int c = 0; c < 3; ++c) m.buffer[3 * k + c] = state.q[beam.node_index(k) + c];
    m.stage(b.positions, m.buffer.data());
    if (!m.per_row && !m.envelope) continue;
    b.results.compute(state, m.table);
    if (m.envelope) b.envelope.add(m.table);
    for (std::size_t q = 0; q < b.quantities.size(); ++q)
      m.stage(b.quantities[q], m.table.col(static_cast<Index>(q)).data());
  }
  ++m.rows;
  // data and metadata on disk once a block is complete (and at every flush())
  if (!m.work || m.rows - m.written >= kMaxBlockRows || m.work() - m.work_written >= kWorkPerBlock)
    m.write_rows();
}

void Hdf5Recorder::observe_step(const State& state) {
  Impl& m = *impl_;
  if (!m.envelope_steps) return;
  for (auto& b : m.beams) {
    b.results.compute(state, m.table);
    b.envelope.extend(m.table);
  }
}

void Hdf5Recorder::set_work_counter(std::function<double()> work) {
  impl_->work = std::move(work);
  impl_->work_written = impl_->work ? impl_->work() : 0.0;
}

void Hdf5Recorder::flush() {
  Impl& m = *impl_;
  if (m.failed) return;  // already reported; its rows up to the failure are on disk
  m.write_rows();
  if (m.envelope) {
    for (auto& b : m.beams) {
      if (b.envelope.count() == 0) continue;
      const hid_t g = b.group.get();
      if (b.envelope_written) H5Ldelete(g, "envelope", H5P_DEFAULT);
      Handle env = m.group(g, "envelope");
      m.long_attribute(env.get(), "rows", b.envelope.count());
      const MatX mean = b.envelope.mean();
      const std::pair<const char*, const MatX*> parts[] = {
          {"min", &b.envelope.min()}, {"max", &b.envelope.max()}, {"mean", &mean}};
      for (const auto& [part, table] : parts) {
        Handle pg = m.group(env.get(), part);
        const auto& info = post::beam_quantities();
        for (std::size_t q = 0; q < info.size(); ++q)
          m.array(pg.get(), std::string(info[q].name), {static_cast<hsize_t>(table->rows())},
                  table->col(static_cast<Index>(q)).data(), std::string(info[q].unit).c_str());
      }
      b.envelope_written = true;
    }
  }
  if (m.statistics) {
    const Table t = m.statistics();
    const hid_t root = m.file.get();
    if (m.statistics_written) H5Ldelete(root, "statistics", H5P_DEFAULT);
    Handle g = m.group(root, "statistics");
    m.string_array(g.get(), "channel", t.rows);
    for (std::size_t c = 0; c < t.columns.size(); ++c)
      m.array(g.get(), t.columns[c], {static_cast<hsize_t>(t.values.rows())},
              t.values.col(static_cast<Index>(c)).data(), nullptr);
    m.statistics_written = true;
  }
  m.check_status(H5Fflush(m.file.get(), H5F_SCOPE_GLOBAL), "H5Fflush");
}

void Hdf5Recorder::set_statistics(std::function<Table()> source) {
  impl_->statistics = std::move(source);
}

}  // namespace seaflex::io
