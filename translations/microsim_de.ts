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
    <message>
        <source>each pose must be 16 numbers (a 4 by 4 matrix, row-major)</source>
        <translation>jede Pose muss aus 16 Zahlen bestehen (eine 4×4-Matrix, zeilenweise)</translation>
    </message>
    <message>
        <source>each fiducial and check point needs "tracker" and "scene" as [x, y, z]</source>
        <translation>jeder Referenz- und Prüfpunkt braucht „tracker“ und „scene“ als [x, y, z]</translation>
    </message>
    <message>
        <source>Read the poses or points from the JSON &lt;file&gt;.</source>
        <translation>Die Posen oder Punkte aus der JSON-Datei &lt;file&gt; lesen.</translation>
    </message>
    <message>
        <source>Write the result as JSON to &lt;file&gt;.</source>
        <translation>Das Ergebnis als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>pivot or register</source>
        <translation>pivot oder register</translation>
    </message>
    <message>
        <source>Usage: microsim-cli calibrate pivot|register --input FILE [--json FILE]</source>
        <translation>Aufruf: microsim-cli calibrate pivot|register --input DATEI [--json DATEI]</translation>
    </message>
    <message>
        <source>microsim-cli calibrate: say pivot or register, and give --input FILE</source>
        <translation>microsim-cli calibrate: pivot oder register angeben und --input DATEI nennen</translation>
    </message>
    <message>
        <source>microsim-cli calibrate: cannot read %1</source>
        <translation>microsim-cli calibrate: %1 kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>microsim-cli calibrate: %1 is not a JSON object: %2</source>
        <translation>microsim-cli calibrate: %1 ist kein JSON-Objekt: %2</translation>
    </message>
    <message>
        <source>microsim-cli calibrate: cannot write %1</source>
        <translation>microsim-cli calibrate: %1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>run a scene on recorded or scripted input (hash, events, timings)</source>
        <translation>eine Szene mit aufgezeichneter oder geskripteter Eingabe ausführen (Hash, Ereignisse, Zeiten)</translation>
    </message>
    <message>
        <source>record what an OpenIGTLink tracker sends</source>
        <translation>aufzeichnen, was ein OpenIGTLink-Tracker sendet</translation>
    </message>
    <message>
        <source>pivot calibration or tracker-to-scene registration from a file</source>
        <translation>Pivot-Kalibrierung oder Tracker-Szene-Registrierung aus einer Datei</translation>
    </message>
    <message numerus="yes">
        <source>forceps grabs %n tissue node(s)</source>
        <translation><numerusform>Pinzette greift %n Gewebeknoten</numerusform><numerusform>Pinzette greift %n Gewebeknoten</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>forceps releases %n tissue node(s)</source>
        <translation><numerusform>Pinzette lässt %n Gewebeknoten los</numerusform><numerusform>Pinzette lässt %n Gewebeknoten los</numerusform></translation>
    </message>
    <message>
        <source>forceps grips the suture at node %1</source>
        <translation>Pinzette fasst den Faden an Knoten %1</translation>
    </message>
    <message>
        <source>forceps lets go of the suture</source>
        <translation>Pinzette lässt den Faden los</translation>
    </message>
    <message>
        <source>needle enters a wall</source>
        <translation>Nadel tritt in eine Wand ein</translation>
    </message>
    <message>
        <source>needle leaves a wall</source>
        <translation>Nadel tritt aus einer Wand aus</translation>
    </message>
    <message numerus="yes">
        <source>scalpel cuts %n link(s)</source>
        <translation><numerusform>Skalpell durchtrennt %n Feder</numerusform><numerusform>Skalpell durchtrennt %n Federn</numerusform></translation>
    </message>
    <message>
        <source>suture breaks at link %1</source>
        <translation>Faden reißt an Glied %1</translation>
    </message>
    <message>
        <source>suture slips out of a pierce</source>
        <translation>Faden rutscht aus einem Durchstich</translation>
    </message>
    <message>
        <source>input frame rejected</source>
        <translation>Eingabebild verworfen</translation>
    </message>
    <message>
        <source>cannot open the recording</source>
        <translation>die Aufzeichnung kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>cannot write the recording</source>
        <translation>die Aufzeichnung kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>not a microsim recording</source>
        <translation>keine microsim-Aufzeichnung</translation>
    </message>
    <message>
        <source>recording from a newer version</source>
        <translation>Aufzeichnung einer neueren Version</translation>
    </message>
    <message>
        <source>unfinished recording (no end record)</source>
        <translation>unvollständige Aufzeichnung (kein Abschlusseintrag)</translation>
    </message>
    <message>
        <source>damaged recording (checksum mismatch)</source>
        <translation>beschädigte Aufzeichnung (Prüfsumme stimmt nicht)</translation>
    </message>
    <message>
        <source>damaged recording (malformed frame)</source>
        <translation>beschädigte Aufzeichnung (fehlerhaftes Bild)</translation>
    </message>
    <message>
        <source>The scene &lt;file&gt; to run.</source>
        <translation>Die auszuführende Szene &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Replay the input frames of the recording &lt;file&gt;.</source>
        <translation>Die Eingabebilder der Aufzeichnung &lt;file&gt; abspielen.</translation>
    </message>
    <message>
        <source>Generate the input instead: 'stitch' (one scripted stitch).</source>
        <translation>Stattdessen die Eingabe erzeugen: „stitch“ (eine geskriptete Naht).</translation>
    </message>
    <message>
        <source>Record every input frame to &lt;file&gt;.</source>
        <translation>Jedes Eingabebild in &lt;file&gt; aufzeichnen.</translation>
    </message>
    <message>
        <source>Run &lt;n&gt; steps (default: every input frame, else 100).</source>
        <translation>&lt;n&gt; Schritte ausführen (Vorgabe: jedes Eingabebild, sonst 100).</translation>
    </message>
    <message>
        <source>Stop each tissue solve at the step budget (not reproducible).</source>
        <translation>Jede Gewebelösung am Schrittbudget anhalten (nicht reproduzierbar).</translation>
    </message>
    <message>
        <source>Write the hash, events and timings as JSON to &lt;file&gt;.</source>
        <translation>Hash, Ereignisse und Zeiten als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli run --scene FILE [--input REC | --script stitch] [--record REC] [--frames N] [--json OUT]</source>
        <translation>Aufruf: microsim-cli run --scene DATEI [--input AUFZ | --script stitch] [--record AUFZ] [--frames N] [--json AUS]</translation>
    </message>
    <message>
        <source>--scene FILE is required</source>
        <translation>--scene DATEI ist erforderlich</translation>
    </message>
    <message>
        <source>--input and --script exclude each other</source>
        <translation>--input und --script schließen einander aus</translation>
    </message>
    <message>
        <source>unknown script '%1' (known: stitch)</source>
        <translation>unbekanntes Skript „%1“ (bekannt: stitch)</translation>
    </message>
    <message>
        <source>--frames wants a whole number ≥ 0, not '%1'</source>
        <translation>--frames erwartet eine ganze Zahl ≥ 0, nicht „%1“</translation>
    </message>
    <message numerus="yes">
        <source>replaying its %n complete frame(s)</source>
        <translation><numerusform>es wird sein %n vollständiges Bild abgespielt</numerusform><numerusform>es werden seine %n vollständigen Bilder abgespielt</numerusform></translation>
    </message>
    <message>
        <source>(at byte %1)</source>
        <translation>(bei Byte %1)</translation>
    </message>
    <message>
        <source>the stitch script needs a severed vessel, a curved needle and two forceps</source>
        <translation>das Nahtskript braucht ein durchtrenntes Gefäß, eine gebogene Nadel und zwei Pinzetten</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source> of %1 s</source>
        <translation> von %1 s</translation>
    </message>
    <message>
        <source>state hash</source>
        <translation>Zustands-Hash</translation>
    </message>
    <message>
        <source>events</source>
        <translation>Ereignisse</translation>
    </message>
    <message>
        <source>end %1, angle %2°, bite %3 mm, at (%4, %5, %6)</source>
        <translation>Ende %1, Winkel %2°, Stichabstand %3 mm, bei (%4, %5, %6)</translation>
    </message>
    <message>
        <source>collision</source>
        <translation>Kollision</translation>
    </message>
    <message>
        <source>tissue</source>
        <translation>Gewebe</translation>
    </message>
    <message>
        <source>suture</source>
        <translation>Faden</translation>
    </message>
    <message>
        <source>interactions</source>
        <translation>Interaktionen</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>step time (ms)</source>
        <translation>Schrittzeit (ms)</translation>
    </message>
    <message>
        <source>median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>p99</source>
        <translation>p99</translation>
    </message>
    <message>
        <source>max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>OpenIGTLink server to read, HOST:PORT (port 18944 by default).</source>
        <translation>Zu lesender OpenIGTLink-Server, HOST:PORT (Vorgabe Port 18944).</translation>
    </message>
    <message>
        <source>Record for &lt;seconds&gt; (default 10).</source>
        <translation>&lt;seconds&gt; Sekunden lang aufzeichnen (Vorgabe 10).</translation>
    </message>
    <message>
        <source>Write the record as JSON to &lt;file&gt;.</source>
        <translation>Die Aufzeichnung als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Stop when the server closes the link (no reconnection).</source>
        <translation>Anhalten, wenn der Server die Verbindung schließt (keine Neuverbindung).</translation>
    </message>
    <message>
        <source>Refuse poses moving faster than &lt;mm/s&gt; (default 2000).</source>
        <translation>Posen verwerfen, die sich schneller als &lt;mm/s&gt; bewegen (Vorgabe 2000).</translation>
    </message>
    <message>
        <source>Usage: microsim-cli track --igtl HOST:PORT [--duration S] [--json FILE] [--once] [--max-speed MM_S]</source>
        <translation>Aufruf: microsim-cli track --igtl HOST:PORT [--duration S] [--json DATEI] [--once] [--max-speed MM_S]</translation>
    </message>
    <message>
        <source>microsim-cli track: give the server as --igtl HOST:PORT</source>
        <translation>microsim-cli track: den Server als --igtl HOST:PORT angeben</translation>
    </message>
    <message>
        <source>microsim-cli track: --duration and --max-speed take positive numbers</source>
        <translation>microsim-cli track: --duration und --max-speed erwarten positive Zahlen</translation>
    </message>
    <message>
        <source>microsim-cli track: could not connect to %1:%2: %3</source>
        <translation>microsim-cli track: keine Verbindung zu %1:%2: %3</translation>
    </message>
    <message>
        <source>%1 connection(s) to %2:%3</source>
        <translation>%1 Verbindung(en) zu %2:%3</translation>
    </message>
    <message>
        <source>device              received   rate (Hz)   last position (mm)</source>
        <translation>Gerät               empfangen  Rate (Hz)   letzte Position (mm)</translation>
    </message>
    <message>
        <source>rejected: %1</source>
        <translation>verworfen: %1</translation>
    </message>
    <message>
        <source>microsim-cli track: cannot write %1</source>
        <translation>microsim-cli track: %1 kann nicht geschrieben werden</translation>
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