#include "simulator/engine.h"

namespace rung::simulator {

// PL110 manual 2.1.2 and 5.2. SM105 "Riporta il numero della pagina attualmente visualizzata";
// SM106: "Se la pagina esiste ed è abilitata, verrà visualizzata, mentre se il valore scritto
// non è congruente, la visualizzazione rimarrà alla pagina attuale. Una volta richiamata la
// pagina richiesta, la word verrà automaticamente forzata al valore 0"; SM104 the page shown
// first; SWAP "permette di scorrere in modo circolare tutte le pagine rese disponibili". Run
// after the scan, so the start page and the pages the initialisation enables (SM0.1) count
// from the first scan on.
void Engine::serviceTerminal() {
    const Program::TerminalPages &t = m_program->terminal;
    std::int32_t *R = m_words.data();
    const auto enabled = [&](std::int32_t page) {
        if (page >= 1 && page <= t.systemCount)
            return ((static_cast<std::uint32_t>(R[t.systemPages]) >> (page - 1)) & 1u) != 0;
        if (page >= t.firstUser && page < t.firstUser + t.userCount)
            return ((static_cast<std::uint32_t>(R[t.userPages]) >> (page - t.firstUser)) & 1u) != 0;
        return false;
    };
    // The pages in SWAP's order: the system pages, then the user pages.
    const auto next = [&](std::int32_t page) -> std::int32_t {
        const int count = t.systemCount + t.userCount;
        int at = page >= t.firstUser ? t.systemCount + (page - t.firstUser) : page - 1;
        for (int k = 0; k < count; ++k) {
            at = (at + 1 + count) % count;
            const std::int32_t candidate =
                at < t.systemCount ? at + 1 : t.firstUser + (at - t.systemCount);
            if (enabled(candidate))
                return candidate;
        }
        return 0;
    };
    std::int32_t shown = R[t.pageShown];
    if (!enabled(shown))
        shown = enabled(R[t.startPage]) ? R[t.startPage] : next(0);
    if (R[t.pageRequest] != 0 && enabled(R[t.pageRequest])) {
        shown = R[t.pageRequest];
        R[t.pageRequest] = 0;
    }
    const bool swap =
        t.swap.valid() && (static_cast<std::uint32_t>(R[t.swap.word]) & t.swap.mask) != 0;
    if (swap && !m_swapHeld && shown != 0)
        shown = next(shown);
    m_swapHeld = swap;
    R[t.pageShown] = shown;
    // SM107 / SM108: "per il solo ciclo di scansione successivo alla modifica ... Nel ciclo
    // successivo le due aree verranno automaticamente poste a 0" (2.1.2). The keys store
    // between scans; the scan after reads the note, and here it goes.
    for (const std::int32_t w : {t.lastArea, t.lastNumber})
        if (w >= 0)
            R[w] = 0;
}

} // namespace rung::simulator
