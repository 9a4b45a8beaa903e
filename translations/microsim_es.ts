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