#include "compiler_detail.h"

#include <variant>

namespace rung::simulator::detail {

namespace {

std::optional<model::Address> panelAddress(const model::Target &target, const QString &text) {
    if (text.isEmpty())
        return std::nullopt;
    const auto parsed = model::parseAddress(target, text);
    if (const auto *a = std::get_if<model::Address>(&parsed))
        return *a;
    return std::nullopt;
}

} // namespace

void Compiler::compilePanel() {
    const model::FrontPanel &panel = m_target.panel;
    const auto word = [&](const QString &device) -> std::int32_t {
        const auto a = panelAddress(m_target, device);
        return a ? m_layout->word(*a) : -1;
    };
    // The panel's words at power-on (PL110 manual 2.1.2's defaults: SM102 31, SM104 1, ...).
    for (const model::PowerOnValue &v : panel.powerOn)
        if (const std::int32_t w = word(v.device); w >= 0)
            m_program->presetLoads.emplace_back(w, v.value);
    const model::PanelDisplay &d = panel.display;
    if (d.kind != model::DisplayKind::Text || d.pageShownDevice.isEmpty())
        return;
    Program::TerminalPages t;
    t.systemPages = word(d.systemPagesDevice);
    t.userPages = word(d.userPagesDevice);
    t.startPage = word(d.startPageDevice);
    t.pageShown = word(d.pageShownDevice);
    t.pageRequest = word(d.pageRequestDevice);
    t.lastArea = word(d.lastAreaDevice);
    t.lastNumber = word(d.lastNumberDevice);
    t.systemCount = d.systemPages;
    t.firstUser = d.firstUserPage;
    t.userCount = d.userPages;
    // SWAP: the first key ("Il tasto swap permette di scorrere in modo circolare tutte le
    // pagine rese disponibili dal programma ladder", PL110 manual 5.2).
    if (!panel.keys.empty())
        if (const auto a = panelAddress(m_target, panel.keys.front().device))
            t.swap = m_layout->bit(*a);
    if (t.systemPages < 0 || t.userPages < 0 || t.startPage < 0 || t.pageShown < 0 ||
        t.pageRequest < 0)
        return;
    m_program->terminal = t;
}

} // namespace rung::simulator::detail
