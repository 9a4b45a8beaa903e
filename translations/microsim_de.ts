<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="de">
<context>
    <name>Cli</name>
    <message>
        <source>microsim-cli: this build has no benchmarks (configure with -DMICROSIM_BUILD_BENCHMARKS=ON)</source>
        <translation>microsim-cli: dieser Build enthält keine Benchmarks (mit -DMICROSIM_BUILD_BENCHMARKS=ON konfigurieren)</translation>
    </message>
    <message>
        <source>Write the rows as JSON to &lt;file&gt;.</source>
        <translation>Die Zeilen als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Draw the curves to the PNG &lt;file&gt;.</source>
        <translation>Die Kurven in die PNG-Datei &lt;file&gt; zeichnen.</translation>
    </message>
    <message>
        <source>Smaller sizes and fewer repetitions.</source>
        <translation>Kleinere Größen und weniger Wiederholungen.</translation>
    </message>
    <message>
        <source>List the benchmarks.</source>
        <translation>Die Benchmarks auflisten.</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>Diese Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>The benchmark to run.</source>
        <translation>Der auszuführende Benchmark.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli bench NAME [--json FILE] [--plot FILE.png] [--quick]</source>
        <translation>Aufruf: microsim-cli bench NAME [--json DATEI] [--plot DATEI.png] [--quick]</translation>
    </message>
    <message>
        <source>Benchmarks:</source>
        <translation>Benchmarks:</translation>
    </message>
    <message>
        <source>microsim-cli bench: name one benchmark (see --list)</source>
        <translation>microsim-cli bench: bitte genau einen Benchmark nennen (siehe --list)</translation>
    </message>
    <message>
        <source>microsim-cli bench: unknown benchmark '%1' (see --list)</source>
        <translation>microsim-cli bench: unbekannter Benchmark „%1“ (siehe --list)</translation>
    </message>
    <message>
        <source>microsim-cli bench: cannot write %1: %2</source>
        <translation>microsim-cli bench: %1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>microsim-cli bench: '%1' has no curves to plot</source>
        <translation>microsim-cli bench: „%1“ hat keine Kurven zum Zeichnen</translation>
    </message>
    <message>
        <source>microsim-cli bench: cannot write the plot %1</source>
        <translation>microsim-cli bench: das Diagramm %1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>run a benchmark (beside the paper's figures)</source>
        <translation>einen Benchmark ausführen (neben den Werten des Artikels)</translation>
    </message>
    <message>
        <source>Usage: microsim-cli &lt;command&gt; [options]</source>
        <translation>Aufruf: microsim-cli &lt;Befehl&gt; [Optionen]</translation>
    </message>
    <message>
        <source>       microsim-cli --version | --help</source>
        <translation>       microsim-cli --version | --help</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>Befehle:</translation>
    </message>
    <message>
        <source>Run 'microsim-cli &lt;command&gt; --help' for a command's options.</source>
        <translation>„microsim-cli &lt;Befehl&gt; --help“ zeigt die Optionen eines Befehls.</translation>
    </message>
    <message>
        <source>microsim-cli: unknown command '%1'</source>
        <translation>microsim-cli: unbekannter Befehl „%1“</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Micro-anastomosis training simulator</source>
        <translation>Trainingssimulator für Mikroanastomosen</translation>
    </message>
    <message>
        <source>Write a PNG of each main screen to &lt;dir&gt;, then quit.</source>
        <translation>Von jedem Hauptbildschirm ein PNG nach &lt;dir&gt; schreiben und beenden.</translation>
    </message>
    <message>
        <source>dir</source>
        <translation>Verzeichnis</translation>
    </message>
    <message>
        <source>Use the SQLite history file &lt;file&gt; instead of the default.</source>
        <translation>Die SQLite-Verlaufsdatei &lt;file&gt; statt der voreingestellten verwenden.</translation>
    </message>
    <message>
        <source>file</source>
        <translation>Datei</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MainWindow</name>
    <message>
        <source>microsim — micro-anastomosis trainer</source>
        <translation>microsim — Mikroanastomose-Trainer</translation>
    </message>
    <message>
        <source>Drag to orbit the microscope, wheel to zoom.</source>
        <translation>Ziehen dreht das Mikroskop, das Mausrad zoomt.</translation>
    </message>
    <message>
        <source>History: %1 (schema %2)</source>
        <translation>Verlauf: %1 (Schema %2)</translation>
    </message>
    <message>
        <source>History unavailable: cannot create the folder for %1</source>
        <translation>Verlauf nicht verfügbar: der Ordner für %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>History unavailable: cannot open %1</source>
        <translation>Verlauf nicht verfügbar: %1 kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>History unavailable: %1 is not a microsim database or is damaged; it was left untouched</source>
        <translation>Verlauf nicht verfügbar: %1 ist keine microsim-Datenbank oder beschädigt; die Datei wurde nicht verändert</translation>
    </message>
    <message>
        <source>History unavailable: %1 is locked by another program</source>
        <translation>Verlauf nicht verfügbar: %1 ist von einem anderen Programm gesperrt</translation>
    </message>
    <message>
        <source>History unavailable: %1 was written by a newer microsim</source>
        <translation>Verlauf nicht verfügbar: %1 wurde von einer neueren microsim-Version geschrieben</translation>
    </message>
    <message>
        <source>History unavailable: updating %1 failed; it was left as it was</source>
        <translation>Verlauf nicht verfügbar: die Aktualisierung von %1 ist fehlgeschlagen; die Datei blieb unverändert</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>&amp;Einstellungen</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Systemvorgabe</translation>
    </message>
    <message>
        <source>English</source>
        <translation>Englisch</translation>
    </message>
    <message>
        <source>German</source>
        <translation>Deutsch</translation>
    </message>
    <message>
        <source>Spanish</source>
        <translation>Spanisch</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About microsim</source>
        <translation>Ü&amp;ber microsim</translation>
    </message>
    <message>
        <source>The language changes at the next start.</source>
        <translation>Die Sprache wechselt beim nächsten Start.</translation>
    </message>
    <message>
        <source>About microsim</source>
        <translation>Über microsim</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;microsim %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Practise and assessment of microvascular anastomosis under a virtual operating microscope.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;microsim %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Übung und Bewertung mikrovaskulärer Anastomosen unter einem virtuellen Operationsmikroskop.&lt;/p&gt;</translation>
    </message>
</context>
</TS>