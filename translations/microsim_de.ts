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
    <message>
        <source>solve a spring network (scene file or lattice box)</source>
        <translation>ein Federnetz lösen (Szenendatei oder Gitterwürfel)</translation>
    </message>
    <message>
        <source>export the spring network a scene builds</source>
        <translation>das Federnetz exportieren, das eine Szene erzeugt</translation>
    </message>
    <message>
        <source>Write the network as JSON to &lt;file&gt;.</source>
        <translation>Das Netz als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli export --scene FILE | --lattice N [--json FILE]</source>
        <translation>Aufruf: microsim-cli export --scene DATEI | --lattice N [--json DATEI]</translation>
    </message>
    <message>
        <source>unexpected argument '%1'</source>
        <translation>unerwartetes Argument „%1“</translation>
    </message>
    <message>
        <source>objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <source>nodes</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>links</source>
        <translation>Federn</translation>
    </message>
    <message>
        <source>fixed</source>
        <translation>fest</translation>
    </message>
    <message>
        <source>controls</source>
        <translation>Steuerknoten</translation>
    </message>
    <message>
        <source>triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>converged</source>
        <translation>konvergiert</translation>
    </message>
    <message>
        <source>iteration limit</source>
        <translation>Iterationsgrenze</translation>
    </message>
    <message>
        <source>time limit</source>
        <translation>Zeitgrenze</translation>
    </message>
    <message>
        <source>diverged (state restored)</source>
        <translation>divergiert (Zustand wiederhergestellt)</translation>
    </message>
    <message>
        <source>invalid input</source>
        <translation>ungültige Eingabe</translation>
    </message>
    <message>
        <source>--%1 wants a number in [%2, %3), not '%4'</source>
        <translation>--%1 erwartet eine Zahl in [%2, %3), nicht „%4“</translation>
    </message>
    <message>
        <source>The solver: %1 (default: the scene's, else qss).</source>
        <translation>Der Löser: %1 (Vorgabe: der der Szene, sonst qss).</translation>
    </message>
    <message>
        <source>Stop after &lt;k&gt; iterations.</source>
        <translation>Nach &lt;k&gt; Iterationen anhalten.</translation>
    </message>
    <message>
        <source>Stop after &lt;t&gt; milliseconds of wall-clock time.</source>
        <translation>Nach &lt;t&gt; Millisekunden Echtzeit anhalten.</translation>
    </message>
    <message>
        <source>qss per-level cutout ε in mm (0 = off).</source>
        <translation>qss-Abbruchschwelle ε je Ebene in mm (0 = aus).</translation>
    </message>
    <message>
        <source>qss step scale in mm per force unit (0 = automatic).</source>
        <translation>qss-Schrittweite in mm je Krafteinheit (0 = automatisch).</translation>
    </message>
    <message>
        <source>qss momentum β in [0, 1).</source>
        <translation>qss-Impuls β in [0, 1).</translation>
    </message>
    <message>
        <source>Stop once the relative residual is below &lt;r&gt;.</source>
        <translation>Anhalten, sobald das relative Residuum unter &lt;r&gt; liegt.</translation>
    </message>
    <message>
        <source>Write positions and the report as JSON to &lt;file&gt;.</source>
        <translation>Positionen und Bericht als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli solve --scene FILE | --lattice N [--solver NAME] (--iterations K | --budget-ms T) [options]</source>
        <translation>Aufruf: microsim-cli solve --scene DATEI | --lattice N [--solver NAME] (--iterations K | --budget-ms T) [Optionen]</translation>
    </message>
    <message>
        <source>--iterations wants a whole number ≥ 1, not '%1'</source>
        <translation>--iterations erwartet eine ganze Zahl ≥ 1, nicht „%1“</translation>
    </message>
    <message>
        <source>unknown solver '%1' (known: %2)</source>
        <translation>unbekannter Löser „%1“ (bekannt: %2)</translation>
    </message>
    <message>
        <source>the scene names an unknown solver '%1'</source>
        <translation>die Szene nennt einen unbekannten Löser „%1“</translation>
    </message>
    <message>
        <source>give --iterations K or --budget-ms T (or put them in the scene's "solver")</source>
        <translation>--iterations K oder --budget-ms T angeben (oder im „solver“ der Szene festlegen)</translation>
    </message>
    <message>
        <source>solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>iterations</source>
        <translation>Iterationen</translation>
    </message>
    <message>
        <source>seconds</source>
        <translation>Sekunden</translation>
    </message>
    <message>
        <source>residual</source>
        <translation>Residuum</translation>
    </message>
    <message>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>cannot open the scene file</source>
        <translation>die Szenendatei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>not valid JSON</source>
        <translation>kein gültiges JSON</translation>
    </message>
    <message>
        <source>wrong type or length</source>
        <translation>falscher Typ oder falsche Länge</translation>
    </message>
    <message>
        <source>required field missing</source>
        <translation>Pflichtfeld fehlt</translation>
    </message>
    <message>
        <source>unknown field</source>
        <translation>unbekanntes Feld</translation>
    </message>
    <message>
        <source>unknown object type</source>
        <translation>unbekannter Objekttyp</translation>
    </message>
    <message>
        <source>node index out of range</source>
        <translation>Knotenindex außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>link joins a node to itself</source>
        <translation>Feder verbindet einen Knoten mit sich selbst</translation>
    </message>
    <message>
        <source>value must not be negative</source>
        <translation>Wert darf nicht negativ sein</translation>
    </message>
    <message>
        <source>number is not finite</source>
        <translation>Zahl ist nicht endlich</translation>
    </message>
    <message>
        <source>node is controlled twice</source>
        <translation>Knoten wird doppelt gesteuert</translation>
    </message>
    <message>
        <source>value out of range</source>
        <translation>Wert außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>cannot import the surface mesh</source>
        <translation>das Oberflächennetz kann nicht importiert werden</translation>
    </message>
    <message>
        <source>file not found</source>
        <translation>Datei nicht gefunden</translation>
    </message>
    <message>
        <source>unreadable</source>
        <translation>unlesbar</translation>
    </message>
    <message>
        <source>no triangles</source>
        <translation>keine Dreiecke</translation>
    </message>
    <message>
        <source>non-finite coordinates</source>
        <translation>nicht endliche Koordinaten</translation>
    </message>
    <message>
        <source>bad import options</source>
        <translation>ungültige Importoptionen</translation>
    </message>
    <message>
        <source>(field %1)</source>
        <translation>(Feld %1)</translation>
    </message>
    <message>
        <source>give exactly one of --scene FILE and --lattice N</source>
        <translation>genau eines von --scene DATEI und --lattice N angeben</translation>
    </message>
    <message>
        <source>--stiffness applies to --lattice only</source>
        <translation>--stiffness gilt nur für --lattice</translation>
    </message>
    <message>
        <source>--lattice wants a whole number from 2 to 200, not '%1'</source>
        <translation>--lattice erwartet eine ganze Zahl von 2 bis 200, nicht „%1“</translation>
    </message>
    <message>
        <source>--stiffness wants a number ≥ 0, not '%1'</source>
        <translation>--stiffness erwartet eine Zahl ≥ 0, nicht „%1“</translation>
    </message>
    <message>
        <source>Read the spring network from the scene &lt;file&gt;.</source>
        <translation>Das Federnetz aus der Szene &lt;file&gt; lesen.</translation>
    </message>
    <message>
        <source>Use the paper's N×N×N lattice box (bottom fixed, top middle node pulled up 1 mm).</source>
        <translation>Den N×N×N-Gitterwürfel des Artikels verwenden (Boden fest, mittlerer Knoten oben 1 mm nach oben gezogen).</translation>
    </message>
    <message>
        <source>Link stiffness of the --lattice box in g/s² (default 10).</source>
        <translation>Federsteifigkeit des --lattice-Würfels in g/s² (Vorgabe 10).</translation>
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