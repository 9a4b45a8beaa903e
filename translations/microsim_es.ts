<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="es">
<context>
    <name>Cli</name>
    <message>
        <source>microsim-cli: this build has no benchmarks (configure with -DMICROSIM_BUILD_BENCHMARKS=ON)</source>
        <translation>microsim-cli: esta compilación no incluye benchmarks (configure con -DMICROSIM_BUILD_BENCHMARKS=ON)</translation>
    </message>
    <message>
        <source>Write the rows as JSON to &lt;file&gt;.</source>
        <translation>Escribir las filas como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Draw the curves to the PNG &lt;file&gt;.</source>
        <translation>Dibujar las curvas en el PNG &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Smaller sizes and fewer repetitions.</source>
        <translation>Tamaños menores y menos repeticiones.</translation>
    </message>
    <message>
        <source>List the benchmarks.</source>
        <translation>Listar los benchmarks.</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>Mostrar esta ayuda.</translation>
    </message>
    <message>
        <source>The benchmark to run.</source>
        <translation>El benchmark que se ejecutará.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli bench NAME [--json FILE] [--plot FILE.png] [--quick]</source>
        <translation>Uso: microsim-cli bench NOMBRE [--json ARCHIVO] [--plot ARCHIVO.png] [--quick]</translation>
    </message>
    <message>
        <source>Benchmarks:</source>
        <translation>Benchmarks:</translation>
    </message>
    <message>
        <source>microsim-cli bench: name one benchmark (see --list)</source>
        <translation>microsim-cli bench: indique un solo benchmark (vea --list)</translation>
    </message>
    <message>
        <source>microsim-cli bench: unknown benchmark '%1' (see --list)</source>
        <translation>microsim-cli bench: benchmark desconocido «%1» (vea --list)</translation>
    </message>
    <message>
        <source>microsim-cli bench: cannot write %1: %2</source>
        <translation>microsim-cli bench: no se puede escribir %1: %2</translation>
    </message>
    <message>
        <source>microsim-cli bench: '%1' has no curves to plot</source>
        <translation>microsim-cli bench: «%1» no tiene curvas que dibujar</translation>
    </message>
    <message>
        <source>microsim-cli bench: cannot write the plot %1</source>
        <translation>microsim-cli bench: no se puede escribir el gráfico %1</translation>
    </message>
    <message>
        <source>run a benchmark (beside the paper's figures)</source>
        <translation>ejecutar un benchmark (junto a las cifras del artículo)</translation>
    </message>
    <message>
        <source>Usage: microsim-cli &lt;command&gt; [options]</source>
        <translation>Uso: microsim-cli &lt;orden&gt; [opciones]</translation>
    </message>
    <message>
        <source>       microsim-cli --version | --help</source>
        <translation>    microsim-cli --version | --help</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>Órdenes:</translation>
    </message>
    <message>
        <source>Run 'microsim-cli &lt;command&gt; --help' for a command's options.</source>
        <translation>Ejecute «microsim-cli &lt;orden&gt; --help» para ver las opciones de una orden.</translation>
    </message>
    <message>
        <source>microsim-cli: unknown command '%1'</source>
        <translation>microsim-cli: orden desconocida «%1»</translation>
    </message>
    <message>
        <source>solve a spring network (scene file or lattice box)</source>
        <translation>resolver una red de muelles (archivo de escena o cubo reticular)</translation>
    </message>
    <message>
        <source>export the spring network a scene builds</source>
        <translation>exportar la red de muelles que construye una escena</translation>
    </message>
    <message>
        <source>Write the network as JSON to &lt;file&gt;.</source>
        <translation>Escribir la red como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli export --scene FILE | --lattice N [--json FILE]</source>
        <translation>Uso: microsim-cli export --scene ARCHIVO | --lattice N [--json ARCHIVO]</translation>
    </message>
    <message>
        <source>unexpected argument '%1'</source>
        <translation>argumento inesperado «%1»</translation>
    </message>
    <message>
        <source>objects</source>
        <translation>objetos</translation>
    </message>
    <message>
        <source>nodes</source>
        <translation>nodos</translation>
    </message>
    <message>
        <source>links</source>
        <translation>muelles</translation>
    </message>
    <message>
        <source>fixed</source>
        <translation>fijos</translation>
    </message>
    <message>
        <source>controls</source>
        <translation>nodos de control</translation>
    </message>
    <message>
        <source>triangles</source>
        <translation>triángulos</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>no se puede escribir %1: %2</translation>
    </message>
    <message>
        <source>converged</source>
        <translation>convergido</translation>
    </message>
    <message>
        <source>iteration limit</source>
        <translation>límite de iteraciones</translation>
    </message>
    <message>
        <source>time limit</source>
        <translation>límite de tiempo</translation>
    </message>
    <message>
        <source>diverged (state restored)</source>
        <translation>divergió (estado restaurado)</translation>
    </message>
    <message>
        <source>invalid input</source>
        <translation>entrada no válida</translation>
    </message>
    <message>
        <source>--%1 wants a number in [%2, %3), not '%4'</source>
        <translation>--%1 espera un número en [%2, %3), no «%4»</translation>
    </message>
    <message>
        <source>The solver: %1 (default: the scene's, else qss).</source>
        <translation>El solucionador: %1 (predeterminado: el de la escena, si no qss).</translation>
    </message>
    <message>
        <source>Stop after &lt;k&gt; iterations.</source>
        <translation>Parar tras &lt;k&gt; iteraciones.</translation>
    </message>
    <message>
        <source>Stop after &lt;t&gt; milliseconds of wall-clock time.</source>
        <translation>Parar tras &lt;t&gt; milisegundos de tiempo real.</translation>
    </message>
    <message>
        <source>qss per-level cutout ε in mm (0 = off).</source>
        <translation>corte por nivel ε de qss en mm (0 = desactivado).</translation>
    </message>
    <message>
        <source>qss step scale in mm per force unit (0 = automatic).</source>
        <translation>escala de paso de qss en mm por unidad de fuerza (0 = automática).</translation>
    </message>
    <message>
        <source>qss momentum β in [0, 1).</source>
        <translation>momento β de qss en [0, 1).</translation>
    </message>
    <message>
        <source>Stop once the relative residual is below &lt;r&gt;.</source>
        <translation>Parar cuando el residuo relativo sea menor que &lt;r&gt;.</translation>
    </message>
    <message>
        <source>Write positions and the report as JSON to &lt;file&gt;.</source>
        <translation>Escribir las posiciones y el informe como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli solve --scene FILE | --lattice N [--solver NAME] (--iterations K | --budget-ms T) [options]</source>
        <translation>Uso: microsim-cli solve --scene ARCHIVO | --lattice N [--solver NOMBRE] (--iterations K | --budget-ms T) [opciones]</translation>
    </message>
    <message>
        <source>--iterations wants a whole number ≥ 1, not '%1'</source>
        <translation>--iterations espera un número entero ≥ 1, no «%1»</translation>
    </message>
    <message>
        <source>unknown solver '%1' (known: %2)</source>
        <translation>solucionador desconocido «%1» (conocidos: %2)</translation>
    </message>
    <message>
        <source>the scene names an unknown solver '%1'</source>
        <translation>la escena indica un solucionador desconocido «%1»</translation>
    </message>
    <message>
        <source>give --iterations K or --budget-ms T (or put them in the scene's "solver")</source>
        <translation>indique --iterations K o --budget-ms T (o póngalos en el «solver» de la escena)</translation>
    </message>
    <message>
        <source>solver</source>
        <translation>solucionador</translation>
    </message>
    <message>
        <source>iterations</source>
        <translation>iteraciones</translation>
    </message>
    <message>
        <source>seconds</source>
        <translation>segundos</translation>
    </message>
    <message>
        <source>residual</source>
        <translation>residuo</translation>
    </message>
    <message>
        <source>status</source>
        <translation>estado</translation>
    </message>
    <message>
        <source>cannot open the scene file</source>
        <translation>no se puede abrir el archivo de escena</translation>
    </message>
    <message>
        <source>not valid JSON</source>
        <translation>JSON no válido</translation>
    </message>
    <message>
        <source>wrong type or length</source>
        <translation>tipo o longitud incorrectos</translation>
    </message>
    <message>
        <source>required field missing</source>
        <translation>falta un campo obligatorio</translation>
    </message>
    <message>
        <source>unknown field</source>
        <translation>campo desconocido</translation>
    </message>
    <message>
        <source>unknown object type</source>
        <translation>tipo de objeto desconocido</translation>
    </message>
    <message>
        <source>node index out of range</source>
        <translation>índice de nodo fuera de rango</translation>
    </message>
    <message>
        <source>link joins a node to itself</source>
        <translation>el muelle une un nodo consigo mismo</translation>
    </message>
    <message>
        <source>value must not be negative</source>
        <translation>el valor no puede ser negativo</translation>
    </message>
    <message>
        <source>number is not finite</source>
        <translation>el número no es finito</translation>
    </message>
    <message>
        <source>node is controlled twice</source>
        <translation>el nodo se controla dos veces</translation>
    </message>
    <message>
        <source>value out of range</source>
        <translation>valor fuera de rango</translation>
    </message>
    <message>
        <source>cannot import the surface mesh</source>
        <translation>no se puede importar la malla de superficie</translation>
    </message>
    <message>
        <source>file not found</source>
        <translation>archivo no encontrado</translation>
    </message>
    <message>
        <source>unreadable</source>
        <translation>ilegible</translation>
    </message>
    <message>
        <source>no triangles</source>
        <translation>sin triángulos</translation>
    </message>
    <message>
        <source>non-finite coordinates</source>
        <translation>coordenadas no finitas</translation>
    </message>
    <message>
        <source>bad import options</source>
        <translation>opciones de importación no válidas</translation>
    </message>
    <message>
        <source>(field %1)</source>
        <translation>(campo %1)</translation>
    </message>
    <message>
        <source>give exactly one of --scene FILE and --lattice N</source>
        <translation>indique exactamente uno de --scene ARCHIVO y --lattice N</translation>
    </message>
    <message>
        <source>--stiffness applies to --lattice only</source>
        <translation>--stiffness solo se aplica a --lattice</translation>
    </message>
    <message>
        <source>--lattice wants a whole number from 2 to 200, not '%1'</source>
        <translation>--lattice espera un número entero de 2 a 200, no «%1»</translation>
    </message>
    <message>
        <source>--stiffness wants a number ≥ 0, not '%1'</source>
        <translation>--stiffness espera un número ≥ 0, no «%1»</translation>
    </message>
    <message>
        <source>Read the spring network from the scene &lt;file&gt;.</source>
        <translation>Leer la red de muelles de la escena &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Use the paper's N×N×N lattice box (bottom fixed, top middle node pulled up 1 mm).</source>
        <translation>Usar el cubo reticular N×N×N del artículo (base fija, nodo central superior desplazado 1 mm hacia arriba).</translation>
    </message>
    <message>
        <source>Link stiffness of the --lattice box in g/s² (default 10).</source>
        <translation>Rigidez de los muelles del cubo --lattice en g/s² (predeterminada 10).</translation>
    </message>
    <message>
        <source>each pose must be 16 numbers (a 4 by 4 matrix, row-major)</source>
        <translation>cada pose debe tener 16 números (una matriz 4×4, por filas)</translation>
    </message>
    <message>
        <source>each fiducial and check point needs "tracker" and "scene" as [x, y, z]</source>
        <translation>cada punto fiducial y de control necesita «tracker» y «scene» como [x, y, z]</translation>
    </message>
    <message>
        <source>Read the poses or points from the JSON &lt;file&gt;.</source>
        <translation>Leer las poses o los puntos del JSON &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Write the result as JSON to &lt;file&gt;.</source>
        <translation>Escribir el resultado como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>pivot or register</source>
        <translation>pivot o register</translation>
    </message>
    <message>
        <source>Usage: microsim-cli calibrate pivot|register --input FILE [--json FILE]</source>
        <translation>Uso: microsim-cli calibrate pivot|register --input ARCHIVO [--json ARCHIVO]</translation>
    </message>
    <message>
        <source>microsim-cli calibrate: say pivot or register, and give --input FILE</source>
        <translation>microsim-cli calibrate: indique pivot o register, y --input ARCHIVO</translation>
    </message>
    <message>
        <source>microsim-cli calibrate: cannot read %1</source>
        <translation>microsim-cli calibrate: no se puede leer %1</translation>
    </message>
    <message>
        <source>microsim-cli calibrate: %1 is not a JSON object: %2</source>
        <translation>microsim-cli calibrate: %1 no es un objeto JSON: %2</translation>
    </message>
    <message>
        <source>microsim-cli calibrate: cannot write %1</source>
        <translation>microsim-cli calibrate: no se puede escribir %1</translation>
    </message>
    <message>
        <source>run a scene on recorded or scripted input (hash, events, timings)</source>
        <translation>ejecutar una escena con entrada grabada o programada (hash, eventos, tiempos)</translation>
    </message>
    <message>
        <source>record what an OpenIGTLink tracker sends</source>
        <translation>grabar lo que envía un localizador OpenIGTLink</translation>
    </message>
    <message>
        <source>pivot calibration or tracker-to-scene registration from a file</source>
        <translation>calibración de pivote o registro localizador-escena desde un archivo</translation>
    </message>
    <message numerus="yes">
        <source>forceps grabs %n tissue node(s)</source>
        <translation><numerusform>la pinza sujeta %n nodo de tejido</numerusform><numerusform>la pinza sujeta %n nodos de tejido</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>forceps releases %n tissue node(s)</source>
        <translation><numerusform>la pinza suelta %n nodo de tejido</numerusform><numerusform>la pinza suelta %n nodos de tejido</numerusform></translation>
    </message>
    <message>
        <source>forceps grips the suture at node %1</source>
        <translation>la pinza sujeta la sutura en el nodo %1</translation>
    </message>
    <message>
        <source>forceps lets go of the suture</source>
        <translation>la pinza suelta la sutura</translation>
    </message>
    <message>
        <source>needle enters a wall</source>
        <translation>la aguja entra en una pared</translation>
    </message>
    <message>
        <source>needle leaves a wall</source>
        <translation>la aguja sale de una pared</translation>
    </message>
    <message numerus="yes">
        <source>scalpel cuts %n link(s)</source>
        <translation><numerusform>el bisturí corta %n muelle</numerusform><numerusform>el bisturí corta %n muelles</numerusform></translation>
    </message>
    <message>
        <source>suture breaks at link %1</source>
        <translation>la sutura se rompe en el eslabón %1</translation>
    </message>
    <message>
        <source>suture slips out of a pierce</source>
        <translation>la sutura se sale de una punción</translation>
    </message>
    <message>
        <source>input frame rejected</source>
        <translation>fotograma de entrada rechazado</translation>
    </message>
    <message>
        <source>cannot open the recording</source>
        <translation>no se puede abrir la grabación</translation>
    </message>
    <message>
        <source>cannot write the recording</source>
        <translation>no se puede escribir la grabación</translation>
    </message>
    <message>
        <source>not a microsim recording</source>
        <translation>no es una grabación de microsim</translation>
    </message>
    <message>
        <source>recording from a newer version</source>
        <translation>grabación de una versión más reciente</translation>
    </message>
    <message>
        <source>unfinished recording (no end record)</source>
        <translation>grabación incompleta (sin registro final)</translation>
    </message>
    <message>
        <source>damaged recording (checksum mismatch)</source>
        <translation>grabación dañada (la suma de comprobación no coincide)</translation>
    </message>
    <message>
        <source>damaged recording (malformed frame)</source>
        <translation>grabación dañada (fotograma mal formado)</translation>
    </message>
    <message>
        <source>The scene &lt;file&gt; to run.</source>
        <translation>La escena &lt;file&gt; que se ejecutará.</translation>
    </message>
    <message>
        <source>Replay the input frames of the recording &lt;file&gt;.</source>
        <translation>Reproducir los fotogramas de entrada de la grabación &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Generate the input instead: 'stitch' (one scripted stitch).</source>
        <translation>Generar la entrada en su lugar: «stitch» (un punto programado).</translation>
    </message>
    <message>
        <source>Record every input frame to &lt;file&gt;.</source>
        <translation>Grabar cada fotograma de entrada en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Run &lt;n&gt; steps (default: every input frame, else 100).</source>
        <translation>Ejecutar &lt;n&gt; pasos (predeterminado: cada fotograma de entrada, si no 100).</translation>
    </message>
    <message>
        <source>Stop each tissue solve at the step budget (not reproducible).</source>
        <translation>Detener cada resolución del tejido en el presupuesto del paso (no reproducible).</translation>
    </message>
    <message>
        <source>Write the hash, events and timings as JSON to &lt;file&gt;.</source>
        <translation>Escribir el hash, los eventos y los tiempos como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli run --scene FILE [--input REC | --script stitch] [--record REC] [--frames N] [--json OUT]</source>
        <translation>Uso: microsim-cli run --scene ARCHIVO [--input GRAB | --script stitch] [--record GRAB] [--frames N] [--json SALIDA]</translation>
    </message>
    <message>
        <source>--scene FILE is required</source>
        <translation>--scene ARCHIVO es obligatorio</translation>
    </message>
    <message>
        <source>--input and --script exclude each other</source>
        <translation>--input y --script se excluyen mutuamente</translation>
    </message>
    <message>
        <source>unknown script '%1' (known: stitch)</source>
        <translation>guion desconocido «%1» (conocido: stitch)</translation>
    </message>
    <message>
        <source>--frames wants a whole number ≥ 0, not '%1'</source>
        <translation>--frames espera un número entero ≥ 0, no «%1»</translation>
    </message>
    <message numerus="yes">
        <source>replaying its %n complete frame(s)</source>
        <translation><numerusform>se reproduce su %n fotograma completo</numerusform><numerusform>se reproducen sus %n fotogramas completos</numerusform></translation>
    </message>
    <message>
        <source>(at byte %1)</source>
        <translation>(en el byte %1)</translation>
    </message>
    <message>
        <source>the stitch script needs a severed vessel, a curved needle and two forceps</source>
        <translation>el guion del punto necesita un vaso seccionado, una aguja curva y dos pinzas</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>escena</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source> of %1 s</source>
        <translation> de %1 s</translation>
    </message>
    <message>
        <source>state hash</source>
        <translation>hash del estado</translation>
    </message>
    <message>
        <source>events</source>
        <translation>eventos</translation>
    </message>
    <message>
        <source>end %1, angle %2°, bite %3 mm, at (%4, %5, %6)</source>
        <translation>extremo %1, ángulo %2°, distancia al borde %3 mm, en (%4, %5, %6)</translation>
    </message>
    <message>
        <source>collision</source>
        <translation>colisión</translation>
    </message>
    <message>
        <source>tissue</source>
        <translation>tejido</translation>
    </message>
    <message>
        <source>suture</source>
        <translation>sutura</translation>
    </message>
    <message>
        <source>interactions</source>
        <translation>interacciones</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>step time (ms)</source>
        <translation>tiempo por paso (ms)</translation>
    </message>
    <message>
        <source>median</source>
        <translation>mediana</translation>
    </message>
    <message>
        <source>p99</source>
        <translation>p99</translation>
    </message>
    <message>
        <source>max</source>
        <translation>máx.</translation>
    </message>
    <message>
        <source>OpenIGTLink server to read, HOST:PORT (port 18944 by default).</source>
        <translation>Servidor OpenIGTLink que leer, HOST:PUERTO (puerto 18944 por defecto).</translation>
    </message>
    <message>
        <source>Record for &lt;seconds&gt; (default 10).</source>
        <translation>Grabar durante &lt;seconds&gt; segundos (predeterminado 10).</translation>
    </message>
    <message>
        <source>Write the record as JSON to &lt;file&gt;.</source>
        <translation>Escribir la grabación como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Stop when the server closes the link (no reconnection).</source>
        <translation>Parar cuando el servidor cierre el enlace (sin reconexión).</translation>
    </message>
    <message>
        <source>Refuse poses moving faster than &lt;mm/s&gt; (default 2000).</source>
        <translation>Rechazar poses que se muevan más rápido que &lt;mm/s&gt; (predeterminado 2000).</translation>
    </message>
    <message>
        <source>Usage: microsim-cli track --igtl HOST:PORT [--duration S] [--json FILE] [--once] [--max-speed MM_S]</source>
        <translation>Uso: microsim-cli track --igtl HOST:PUERTO [--duration S] [--json ARCHIVO] [--once] [--max-speed MM_S]</translation>
    </message>
    <message>
        <source>microsim-cli track: give the server as --igtl HOST:PORT</source>
        <translation>microsim-cli track: indique el servidor como --igtl HOST:PUERTO</translation>
    </message>
    <message>
        <source>microsim-cli track: --duration and --max-speed take positive numbers</source>
        <translation>microsim-cli track: --duration y --max-speed esperan números positivos</translation>
    </message>
    <message>
        <source>microsim-cli track: could not connect to %1:%2: %3</source>
        <translation>microsim-cli track: no se pudo conectar a %1:%2: %3</translation>
    </message>
    <message>
        <source>%1 connection(s) to %2:%3</source>
        <translation>%1 conexión(es) a %2:%3</translation>
    </message>
    <message>
        <source>device              received   rate (Hz)   last position (mm)</source>
        <translation>dispositivo         recibidas  tasa (Hz)   última posición (mm)</translation>
    </message>
    <message>
        <source>rejected: %1</source>
        <translation>rechazadas: %1</translation>
    </message>
    <message>
        <source>microsim-cli track: cannot write %1</source>
        <translation>microsim-cli track: no se puede escribir %1</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Micro-anastomosis training simulator</source>
        <translation>Simulador de entrenamiento en microanastomosis</translation>
    </message>
    <message>
        <source>Write a PNG of each main screen to &lt;dir&gt;, then quit.</source>
        <translation>Escribir un PNG de cada pantalla principal en &lt;dir&gt; y salir.</translation>
    </message>
    <message>
        <source>dir</source>
        <translation>directorio</translation>
    </message>
    <message>
        <source>Use the SQLite history file &lt;file&gt; instead of the default.</source>
        <translation>Usar el archivo de historial SQLite &lt;file&gt; en lugar del predeterminado.</translation>
    </message>
    <message>
        <source>file</source>
        <translation>archivo</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MainWindow</name>
    <message>
        <source>microsim — micro-anastomosis trainer</source>
        <translation>microsim — entrenador de microanastomosis</translation>
    </message>
    <message>
        <source>Drag to orbit the microscope, wheel to zoom.</source>
        <translation>Arrastre para girar el microscopio; la rueda acerca y aleja.</translation>
    </message>
    <message>
        <source>History: %1 (schema %2)</source>
        <translation>Historial: %1 (esquema %2)</translation>
    </message>
    <message>
        <source>History unavailable: cannot create the folder for %1</source>
        <translation>Historial no disponible: no se puede crear la carpeta de %1</translation>
    </message>
    <message>
        <source>History unavailable: cannot open %1</source>
        <translation>Historial no disponible: no se puede abrir %1</translation>
    </message>
    <message>
        <source>History unavailable: %1 is not a microsim database or is damaged; it was left untouched</source>
        <translation>Historial no disponible: %1 no es una base de datos de microsim o está dañada; no se ha modificado</translation>
    </message>
    <message>
        <source>History unavailable: %1 is locked by another program</source>
        <translation>Historial no disponible: otro programa tiene bloqueado %1</translation>
    </message>
    <message>
        <source>History unavailable: %1 was written by a newer microsim</source>
        <translation>Historial no disponible: %1 fue escrito por una versión más reciente de microsim</translation>
    </message>
    <message>
        <source>History unavailable: updating %1 failed; it was left as it was</source>
        <translation>Historial no disponible: la actualización de %1 falló; quedó como estaba</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>&amp;Configuración</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Predeterminado del sistema</translation>
    </message>
    <message>
        <source>English</source>
        <translation>Inglés</translation>
    </message>
    <message>
        <source>German</source>
        <translation>Alemán</translation>
    </message>
    <message>
        <source>Spanish</source>
        <translation>Español</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Ay&amp;uda</translation>
    </message>
    <message>
        <source>&amp;About microsim</source>
        <translation>&amp;Acerca de microsim</translation>
    </message>
    <message>
        <source>The language changes at the next start.</source>
        <translation>El idioma cambiará en el próximo inicio.</translation>
    </message>
    <message>
        <source>About microsim</source>
        <translation>Acerca de microsim</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;microsim %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Practise and assessment of microvascular anastomosis under a virtual operating microscope.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;microsim %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Práctica y evaluación de anastomosis microvasculares bajo un microscopio quirúrgico virtual.&lt;/p&gt;</translation>
    </message>
</context>
</TS>