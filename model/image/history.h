#pragma once

// The recent past of chosen devices, scan by scan, for the timing chart and a history view.
// After each scan the recorder compares every watched device with its last value and keeps
// only changes, in a ring per device: memory is bounded by the devices times
// changesPerDevice (24 bytes a change), whatever the scan rate. The window this gives is per
// device: the last changesPerDevice changes (a bit toggling every 10 ms scan: 4096 changes
// = 41 s; a traffic light's lamps changing every few seconds: hours). Reads say from which
// scan a device's values are known (knownFrom) instead of guessing before it.
// Not thread-safe: the thread that records reads (or copies out under its own lock).

#include "model/image/memory_layout.h"
#include "model/image/trigger.h"

#include <QtGlobal>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace rung::model {

class HistoryRecorder {
public:
    struct Change {
        quint64 scan = 0; // the scan after which the device had this value
        qint64 timeMs = 0;
        std::int32_t value = 0; // bits: 0 or 1
        friend bool operator==(const Change &, const Change &) = default;
    };

    static constexpr std::size_t kDefaultChangesPerDevice = 4096;

    explicit HistoryRecorder(std::shared_ptr<const MemoryLayout> layout,
                             std::size_t changesPerDevice = kDefaultChangesPerDevice);

    // Starts recording a device from the next record(); false when the layout has no such
    // bit or word. Watching a device twice records it once.
    bool watch(const Address &address);
    // The image word a device's values are recorded from; -1 when it cannot be recorded.
    int wordOf(const Address &address) const;
    // The device's value as recorded, read from its image word (wordOf) holding `word`: a
    // bit's 0/1, else the word (values of the device read elsewhere, as a network's history).
    std::int32_t valueIn(const Address &address, std::int32_t word) const;
    int deviceCount() const { return static_cast<int>(m_devices.size()); }
    std::size_t changesPerDevice() const { return m_capacity; }
    void clear(); // forgets the past, keeps the watched devices

    // After a scan: words is the image in MemoryLayout order. True when the trigger fired in
    // this scan (the moment is then the newest of marks()).
    bool record(quint64 scan, qint64 timeMs, const std::int32_t *words);

    // The trigger, evaluated on every record() (its device is watched from then on); empty:
    // none. False when the layout has no such device. Armed on a running recorder it fires on
    // the next change into the condition, not because the condition already holds; after
    // clear() (power-on, every device 0) a condition that holds at the first record fires.
    bool setTrigger(std::optional<Trigger> trigger);
    // A scan ran that was not recorded (nothing watched): a trigger armed after it is armed
    // on a running PLC, not at power-on.
    void scannedUnrecorded() { m_recorded = true; }
    const std::optional<Trigger> &trigger() const { return m_trigger; }
    struct Mark {
        quint64 scan = 0;
        qint64 timeMs = 0;
        friend bool operator==(const Mark &, const Mark &) = default;
    };
    static constexpr std::size_t kMaxMarks = 1000;
    // When the trigger fired, oldest first: the last kMaxMarks; clear() forgets them.
    std::vector<Mark> marks() const;

    // The device's value after the given scan (at the given virtual time); empty when the
    // device is not watched or the moment is outside what is kept.
    std::optional<std::int32_t> valueAtScan(const Address &address, quint64 scan) const;
    std::optional<std::int32_t> valueAtTime(const Address &address, qint64 timeMs) const;
    // The first scan from which the device's values are known (empty before any record).
    std::optional<quint64> knownFrom(const Address &address) const;
    // The oldest change kept: where the device's window starts, in scans and time.
    std::optional<Change> oldest(const Address &address) const;
    // The value at fromMs (when known) followed by every change up to toMs, oldest first.
    std::vector<Change> changes(const Address &address, qint64 fromMs, qint64 toMs) const;

    // Bytes held by the recorded changes (what the window costs).
    std::size_t memoryBytes() const;

private:
    struct Device {
        Address address;
        int word = -1;
        std::uint32_t mask = 0; // 0: the whole word
    };
    struct Ring {
        std::vector<Change> changes; // grows to the capacity, then wraps
        std::size_t head = 0;        // index of the oldest once full
        const Change &at(std::size_t k) const { return changes[(head + k) % changes.size()]; }
    };

    int find(const Address &address) const;
    static std::int32_t read(const Device &d, std::int32_t word) {
        return d.mask ? std::int32_t((static_cast<std::uint32_t>(word) & d.mask) != 0) : word;
    }
    Device deviceOf(const Address &address) const; // word -1: cannot be recorded
    void rebuildWords();
    template <typename Key> std::optional<std::int32_t> valueAt(int device, Key key) const;

    std::shared_ptr<const MemoryLayout> m_layout;
    std::size_t m_capacity;
    std::vector<Device> m_devices;
    std::map<Address, int> m_index;
    std::vector<std::int32_t> m_last; // per device
    // The record loop compares whole image words, not devices: a bit word holds up to 16
    // watched bits, and a word that did not change needs no look at its devices.
    std::vector<int> m_wordIndex;          // distinct image words of the watched devices
    std::vector<std::int32_t> m_wordValue; // their values at the last record
    std::vector<int> m_wordFirst;          // per distinct word: first entry in m_wordDevices
    std::vector<int> m_wordDevices;        // device indices grouped by word
    // Runs of consecutive image words among m_wordIndex: a run unchanged since the last record
    // is passed over with one memcmp (most of a scan's watched words do not change).
    struct WordRun {
        int word = 0;  // its first image word
        int first = 0; // its first index into m_wordIndex / m_wordValue
        int count = 0;
    };
    std::vector<WordRun> m_wordRuns;
    std::vector<Ring> m_rings;
    std::vector<int> m_fresh; // devices whose first value the next record() stores
    bool m_recorded = false;  // a record() since construction or clear()

    std::optional<Trigger> m_trigger;
    int m_triggerDevice = -1;
    // The condition's input before this scan; empty: take the first recorded value as it.
    std::optional<std::int32_t> m_triggerBefore;
    std::vector<Mark> m_marks; // ring of kMaxMarks
    std::size_t m_marksHead = 0;
};

} // namespace rung::model
